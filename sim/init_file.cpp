// sim/init_file.cpp -- --init-file's checks and what it sets (init_file.hpp).
#include "init_file.hpp"

#include <cmath>
#include <string>

#include <fmt/core.h>

#include "hypergas/edmd/given_state.hpp"
#include "hypergas/error.hpp"
#include "hypergas/geometry.hpp"
#include "hypergas/vec.hpp"
#ifdef HYPERGAS_H5MD
#include "hypergas/h5md/h5md.hpp"
#endif

namespace hypergas::cli {

#ifdef HYPERGAS_H5MD
std::string state_checksum(const h5md::State& s) {
  // FNV-1a, 64 bits: offset basis 14695981039346656037, prime 1099511628211
  std::uint64_t h = 14695981039346656037ULL;
  const auto add = [&](const std::vector<double>& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    for (std::size_t i = 0; i < v.size() * sizeof(double); ++i) {
      h ^= p[i];
      h *= 1099511628211ULL;
    }
  };
  add(s.positions);
  add(s.velocities);
  return fmt::format("{:016x}", h);
}

InitSpecies init_species(const std::vector<double>& mass, const std::vector<std::int32_t>& species,
                         const std::string& file) {
  InitSpecies out;
  for (double m : mass) {
    if (m == 1.0) continue;
    if (out.mass_ratio != 1.0 && m != out.mass_ratio)
      throw InvalidInput(fmt::format("{} holds more than two masses: --init-file reads mass 1 "
                                     "(species 0) and at most one other (species 1)",
                                     file));
    out.mass_ratio = m;
    ++out.heavy;
  }
  if (mass.empty())
    for (std::int32_t k : species)
      if (k != 0)
        throw InvalidInput(fmt::format("{} holds species but no masses: give each particle's "
                                       "mass (/particles/all/mass)",
                                       file));
  return out;
}
#endif

void apply_init_file(options::RunOptions& o) {
#ifndef HYPERGAS_H5MD
  if (o.trajectory_every > 0.0)
    throw InvalidInput("--trajectory-every needs HDF5: this hypergas was built without it "
                       "(install libhdf5-dev and build again: scripts/setup.sh --python)");
#endif
  if (o.init_file.empty()) {
    if (o.was_given("--init-frame")) throw InvalidInput("--init-frame applies with --init-file only");
    return;
  }
#ifndef HYPERGAS_H5MD
  throw InvalidInput("--init-file needs HDF5: this hypergas was built without it (install "
                     "libhdf5-dev and build again: scripts/setup.sh --python)");
#else
  for (const char* k : {"--init", "--temperature", "--fraction", "--mass-ratio"})
    if (o.was_given(k))
      throw InvalidInput(fmt::format("{} describes a generated start: leave it out with "
                                     "--init-file, whose state is the start",
                                     k));
  const h5md::State s = h5md::read_state(o.init_file, o.init_frame);
  const std::string& f = o.init_file;
  o.init_frame_read = static_cast<long long>(s.frame);
  o.init_checksum = state_checksum(s);
  if (o.was_given("--dim") && o.dim != s.dim)
    throw InvalidInput(fmt::format("--dim {} differs from the dimension {} of {} (leave --dim "
                                   "out: the file sets it)",
                                   o.dim, s.dim, f));
  if (o.was_given("--n") && o.n != static_cast<long long>(s.n))
    throw InvalidInput(fmt::format("--n {} differs from the {} particles of {} (leave --n out: "
                                   "the file sets it)",
                                   o.n, s.n, f));
  o.dim = s.dim;
  o.n = static_cast<long long>(s.n);
  // The masses decide the species: mass 1 is species 0 (the unit of mass), one other mass
  // is species 1 (--mass-ratio, --fraction from the file)
  const InitSpecies sp = init_species(s.mass, s.species, f);
  if (sp.mass_ratio != 1.0) {
    o.mass_ratio = sp.mass_ratio;
    o.fraction = static_cast<double>(sp.heavy) / static_cast<double>(s.n);
  }
  if (o.engine_kind() != registry::EngineKind::edmd) return;
  if (s.positions.empty())
    throw InvalidInput(fmt::format("{} holds no positions (a velocity-space state): an EDMD "
                                   "start needs them",
                                   f));
  if (o.was_given("--start-packing"))
    throw InvalidInput("--start-packing compresses a lattice start: leave it out with --init-file");
  const double packing =
      static_cast<double>(s.n) * ball_volume(s.dim, 1.0) / std::pow(s.box, s.dim);
  if (o.was_given("--packing") && std::abs(o.packing - packing) > 1e-9 * packing)
    throw InvalidInput(fmt::format("--packing {} differs from the packing {:.12g} of {} (N "
                                   "spheres of diameter 1 in its box of side {:.12g}; leave "
                                   "--packing out: the file sets it)",
                                   o.packing, packing, f, s.box));
  o.packing = packing;
  // the overlap check here too, so that a bad file is refused before the folder is made
  const edmd::GivenState g{s.positions.data(), s.velocities.data(), s.n, s.box, nullptr};
  try {
    for_dim(s.dim, [&](auto d) { edmd::check_given_state<decltype(d)::value>(g); });
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", f, e.what()));
  }
#endif
}

}  // namespace hypergas::cli
