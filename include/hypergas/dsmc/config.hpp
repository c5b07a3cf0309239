// hypergas/dsmc/config.hpp -- what a DSMC run is: size, model, scheme, seed, initial state.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "hypergas/dsmc/models.hpp"
#include "hypergas/error.hpp"
#include "hypergas/initial_state.hpp"

namespace hypergas::dsmc {

/// Time integration: the exact Kac process or Bird's no-time-counter scheme with a step.
enum class Scheme { exact, ntc };

/// A DSMC run (the collision model is the engine's Model template argument). Time in equilibrium mean collision times; temperatures in energy units with
/// the mass of species 0 equal to 1. Two species: set `initial.mass_ratio` (m1/m0),
/// `initial.fraction` (number fraction of species 1) and, for different initial temperatures,
/// `init = two_temp` with `initial.kT_species`; the engine needs Features{.species = true}.
/// These defaults are those of `hypergas run --engine dsmc` and `hypergas.DSMC` (the option
/// table, options/src/table.cpp, reads them from here).
struct Config {
  std::size_t n = 10000;                      ///< number of particles (2 .. 2^32 - 1)
  double vhs_exponent = 0.5;                  ///< a in the VHS rate |g|^a, 0 <= a <= 1
  Scheme scheme = Scheme::exact;              ///< exact Kac process or NTC
  double dt = 0.01;                           ///< NTC time step (mean collision times)
  std::uint64_t seed = 1;                     ///< all randomness derives from it
  InitialState init = InitialState::delta;    ///< initial velocity state
  InitialParams initial;                      ///< kT, per-species kT, fraction, mass ratio, ...
};

/// Throws InvalidInput if `c` cannot be run.
inline void validate(const Config& c) {
  if (c.n < 2 || c.n > 0xffffffffULL)
    throw InvalidInput("DSMC: n must be in [2, 2^32 - 1], got " + std::to_string(c.n));
  if (!(c.vhs_exponent >= 0.0 && c.vhs_exponent <= 1.0))
    throw InvalidInput("DSMC: VHS exponent must be in [0, 1]");
  if (c.scheme == Scheme::ntc && !(std::isfinite(c.dt) && c.dt > 0.0))
    throw InvalidInput("DSMC: NTC time step must be finite and > 0");
}

}  // namespace hypergas::dsmc
