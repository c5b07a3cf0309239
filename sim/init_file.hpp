// sim/init_file.hpp -- `--init-file FILE.h5 [--init-frame K]`: a run that starts from a
// state in an H5MD file (hypergas/h5md/h5md.hpp), by the command, a sweep plan's init_file
// key, or Python's run(init_file=...).
//
// What the file decides: D and N (a --dim or --n that differs is refused), for EDMD the
// packing fraction (N spheres of diameter 1 in the file's periodic cube; a --packing that
// differs is refused, --start-packing too), the velocities, and EDMD's positions. The
// options that describe a generated start (--init, --temperature, --fraction, --mass-ratio)
// are refused beside it. Species come from the masses: mass 1 is species 0, one other mass
// is species 1 (it sets --mass-ratio and --fraction); more masses are refused. The run starts at t = 0 from the frame (its own clock, its own seed: the file's
// time and step are not carried over).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hypergas/edmd/given_state.hpp"
#include "hypergas/error.hpp"
#include "hypergas/options/run_options.hpp"
#ifdef HYPERGAS_H5MD
#include "hypergas/h5md/h5md.hpp"
#endif

namespace hypergas::cli {

/// Checks --init-file and --init-frame against the other options and sets o.dim, o.n (and,
/// for EDMD, o.packing) from the file: the `adjust` step of options::from_given. Throws
/// InvalidInput with one line. Also records the frame read (o.init_frame_read, the index
/// counted from 0) and its state_checksum (o.init_checksum). Without --init-file: refuses a
/// lone --init-frame. In a build without HDF5 refuses --init-file and --trajectory-every.
void apply_init_file(options::RunOptions& o);

#ifdef HYPERGAS_H5MD
/// The checksum of a state as summary.json's init_checksum records it: FNV-1a 64 of the
/// bytes of its positions (none for a velocity-space state), then of its velocities, as
/// read (doubles in this machine's byte order), as 16 lower-case hex digits.
std::string state_checksum(const h5md::State& s);

/// The species of a file's particles: mass 1 is species 0; every other particle has the one
/// other mass, mass_ratio (1: one species), and there are `heavy` of them. Throws
/// InvalidInput for more than two masses, or species without masses.
struct InitSpecies {
  double mass_ratio = 1.0;
  std::size_t heavy = 0;
};
InitSpecies init_species(const std::vector<double>& mass, const std::vector<std::int32_t>& species,
                         const std::string& file);
#endif

/// Constructs `e` from cfg and the state in frame `frame` of `file` (apply_init_file has
/// checked it against the options): DSMC takes the velocities, EDMD the positions, box and
/// velocities.
template <class Engine>
void emplace_from_file(std::optional<Engine>& e, const typename Engine::Config& cfg,
                       const std::string& file, long long frame) {
#ifdef HYPERGAS_H5MD
  const h5md::State s = h5md::read_state(file, frame);
  constexpr int D = Engine::dim;
  if (s.dim != D || s.n != cfg.n)
    throw InvalidInput(file + ": the file changed since the options were read");
  // species 1: the particles whose mass is not 1 (init_species)
  const InitSpecies sp = init_species(s.mass, s.species, file);
  std::vector<std::uint8_t> species(s.n, 0);
  for (std::size_t i = 0; i < s.mass.size(); ++i) species[i] = s.mass[i] != 1.0;
  if constexpr (requires(const Engine& x) { x.packing(); }) {  // EDMD
    const edmd::GivenState g{s.positions.data(), s.velocities.data(), s.n, s.box,
                             sp.heavy ? species.data() : nullptr};
    e.emplace(cfg, g);
  } else {  // DSMC: velocities only
    using Store = typename Engine::ParticlesT;
    Store p;
    p.resize(s.n);
    for (std::size_t i = 0; i < s.n; ++i)
      for (int a = 0; a < D; ++a) p.velocity(i)[a] = s.velocities[i * D + std::size_t(a)];
    if constexpr (Store::features.species) {
      p.set_species_mass(1, sp.mass_ratio);
      for (std::size_t i = 0; i < s.n; ++i) p.set_species(i, species[i]);
    }
    e.emplace(cfg, std::move(p));
  }
#else
  (void)e, (void)cfg, (void)frame;
  throw InvalidInput("--init-file " + file + ": this hypergas was built without HDF5");
#endif
}

}  // namespace hypergas::cli
