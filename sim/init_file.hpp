// sim/init_file.hpp -- `--init-file FILE.h5 [--init-frame K]`: a run that starts from a
// state in an H5MD file (hypergas/h5md/h5md.hpp), by the command, a sweep plan's init_file
// key, or Python's run(init_file=...).
//
// What the file decides: D and N (a --dim or --n that differs is refused), for EDMD the
// packing fraction (N spheres of diameter 1 in the file's periodic cube; a --packing that
// differs is refused, --start-packing too), the velocities, and EDMD's positions. The
// options that describe a generated start (--init, --temperature, --fraction, --mass-ratio)
// are refused beside it. One species of unit mass: a file whose masses are not all 1 is
// refused. The run starts at t = 0 from the frame (its own clock, its own seed: the file's
// time and step are not carried over).
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "hypergas/edmd/given_state.hpp"
#include "hypergas/error.hpp"
#include "hypergas/options/run_options.hpp"
#ifdef HYPERGAS_H5MD
#include "hypergas/h5md/h5md.hpp"
#endif

namespace hypergas::cli {

/// Checks --init-file and --init-frame against the other options and sets o.dim, o.n (and,
/// for EDMD, o.packing) from the file: the `adjust` step of options::from_given. Throws
/// InvalidInput with one line. Without --init-file: refuses a lone --init-frame. In a build
/// without HDF5 refuses --init-file and --trajectory-every.
void apply_init_file(options::RunOptions& o);

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
  if constexpr (requires(const Engine& x) { x.packing(); }) {  // EDMD
    const edmd::GivenState g{s.positions.data(), s.velocities.data(), s.n, s.box, nullptr};
    e.emplace(cfg, g);
  } else {  // DSMC: velocities only
    typename Engine::ParticlesT p;
    p.resize(s.n);
    for (std::size_t i = 0; i < s.n; ++i)
      for (int a = 0; a < D; ++a) p.velocity(i)[a] = s.velocities[i * D + std::size_t(a)];
    e.emplace(cfg, std::move(p));
  }
#else
  (void)e, (void)cfg, (void)frame;
  throw InvalidInput("--init-file " + file + ": this hypergas was built without HDF5");
#endif
}

}  // namespace hypergas::cli
