// hypergas/dsmc/config.hpp -- what a DSMC run is: size, model, scheme, seed, initial state.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "hypergas/dsmc/models.hpp"
#include "hypergas/error.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/restitution.hpp"

namespace hypergas::dsmc {

/// Time integration: the exact Kac process, Bird's no-time-counter scheme with a step, or
/// the lanes scheme: exact Kac processes of cache-sized lanes of particles, dealt anew
/// every epoch (dsmc/detail/kac_lanes.hpp; its bias is derived in docs/validation.md).
enum class Scheme { exact, ntc, lanes };

/// Energy input of a granular gas (restitution < 1): none (the homogeneous cooling state) or
/// a white-noise force on every particle (a driven steady state; dsmc/granular.hpp).
enum class Drive { none, white_noise };

/// A sheared gas's thermostat (dsmc/shear.hpp): none (viscous heating: scaled velocities and
/// real_time, as for cooling) or isokinetic (the Gaussian thermostat that holds T).
enum class Thermostat { none, isokinetic };

/// The largest shear rate accepted (per mean collision time at kT0): above it a mean
/// collision time holds more than 100 strain units, and the engine's rebases (one per 0.1
/// of strain, O(N) each) would outnumber the collisions a thousandfold.
inline constexpr double max_shear_rate = 100.0;

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
  /// Lanes scheme: particles per lane M (0: 2^19 bytes of velocities, 16384 in 3D; the
  /// gas is cut into L = max(1, round(N / M)) lanes of N / L particles, rounded).
  std::uint32_t lane_size = 0;
  /// Lanes scheme: time between two deals of the particles into lanes (mean collision times).
  /// 2 by measurement: 1.16x the rate of epoch 1 at N = 1e7 in 3D, for a bias of the
  /// Maxwell anisotropy of 2e-4 relative at t = 4 (docs/validation.md, docs/benchmarks.md).
  double epoch = 2.0;
  std::uint64_t seed = 1;                     ///< all randomness derives from it
  InitialState init = InitialState::delta;    ///< initial velocity state
  InitialParams initial;                      ///< kT, per-species kT, fraction, mass ratio, ...
  /// Coefficient of normal restitution alpha in [0, 1]: a collision's impulse along its
  /// normal is scaled by (1 + alpha) / 2 (1: elastic, the seed's kernel bit for bit). With
  /// alpha < 1 the gas cools (dsmc/granular.hpp: scaled velocities, the engine's clock).
  double restitution = 1.0;
  Drive drive = Drive::none;  ///< white_noise: hard spheres with restitution < 1 only
  /// White-noise drive: interval between the velocity kicks (mean collision times).
  double drive_dt = 0.05;
  /// Uniform shear flow u_x = a y (dsmc/shear.hpp): the rate a per mean collision time at
  /// kT0, 0 <= a <= max_shear_rate (0: no flow, the engine of an unsheared gas). D >= 2, the
  /// exact scheme, no drive.
  double shear_rate = 0.0;
  /// With shear_rate > 0: none or isokinetic (elastic collisions only).
  Thermostat thermostat = Thermostat::none;
};

/// Throws InvalidInput if `c` cannot be run.
inline void validate(const Config& c) {
  if (c.n < 2 || c.n > 0xffffffffULL)
    throw InvalidInput("DSMC: n must be in [2, 2^32 - 1], got " + std::to_string(c.n));
  if (!(c.vhs_exponent >= 0.0 && c.vhs_exponent <= 1.0))
    throw InvalidInput("DSMC: VHS exponent must be in [0, 1]");
  if (c.scheme == Scheme::ntc && !(std::isfinite(c.dt) && c.dt > 0.0))
    throw InvalidInput("DSMC: NTC time step must be finite and > 0");
  if (c.scheme == Scheme::lanes) {
    if (!(std::isfinite(c.epoch) && c.epoch > 0.0))
      throw InvalidInput("DSMC: the lanes' epoch must be finite and > 0");
    if (c.lane_size == 1)
      throw InvalidInput("DSMC: a lane needs at least 2 particles (--lane-size >= 2, or 0)");
  }
  check_restitution(c.restitution, "DSMC: ");
  if (c.drive == Drive::white_noise) {
    if (!(c.restitution < 1.0))
      throw InvalidInput("DSMC: the white-noise drive needs a restitution below 1 (an elastic "
                         "gas driven by noise heats without bound)");
    if (!(std::isfinite(c.drive_dt) && c.drive_dt > 0.0 && c.drive_dt <= 1.0))
      throw InvalidInput("DSMC: the drive's kick interval must be in (0, 1]");
  }
  if (!(std::isfinite(c.shear_rate) && c.shear_rate >= 0.0 && c.shear_rate <= max_shear_rate))
    throw InvalidInput("DSMC: the shear rate must be in [0, 100] (per mean collision time)");
  if (c.shear_rate == 0.0 && c.thermostat != Thermostat::none)
    throw InvalidInput("DSMC: a thermostat needs a shear rate > 0 (a gas at rest keeps its "
                       "temperature)");
  if (c.shear_rate != 0.0) {
    if (c.scheme != Scheme::exact)
      throw InvalidInput("DSMC: the shear flow runs on the exact scheme only");
    if (c.drive != Drive::none)
      throw InvalidInput("DSMC: the shear flow and the white-noise drive cannot be combined");
    if (c.thermostat == Thermostat::isokinetic && c.restitution != 1.0)
      throw InvalidInput("DSMC: the isokinetic thermostat holds an elastic gas; a granular "
                         "sheared gas reaches its steady state without one");
  }
}

}  // namespace hypergas::dsmc
