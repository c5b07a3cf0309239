// hypergas/edmd/config.hpp -- what an event-driven MD run is: N, packing, seed, initial state.
#pragma once

#include <cstddef>
#include <cstdint>

#include "hypergas/initial_state.hpp"

namespace hypergas::edmd {

/// Parameters of an EDMD run. Units: sigma (diameter of species 0) = 1, m (mass of species
/// 0) = 1, kT = initial.kT (default 1); time in sigma sqrt(m/kT). The neighbour scan is the
/// engine's Scan template parameter (scan.hpp), not a run parameter.
/// These defaults are those of `hypergas run --engine edmd` and `hypergas.EDMD` (the option
/// table, options/src/table.cpp, reads them from here).
struct Config {
  std::size_t n = 10000;      ///< number of particles (>= 2)
  double packing = 0.1;       ///< target packing fraction eta = sum_i v_D(sigma_i/2) / L^D
  /// Packing fraction of the lattice start, if below `packing` (0: start at `packing`):
  /// the diameters start at (start_packing / packing)^(1/D) of their size, and the
  /// Lubachevsky–Stillinger compression (growth_rate) grows them to it. The way to a dense
  /// fluid or glass: a lattice started at the target stays a crystal above melting.
  double start_packing = 0.0;
  std::uint64_t seed = 1;     ///< seed of the positions and velocities
  InitialState init = InitialState::maxwell;  ///< initial velocity state (initial_state.hpp)
  InitialParams initial{};    ///< kT, mixture fraction and mass ratio of the state
  /// Collisions per particle between renumberings of the particles by position (memory
  /// locality, Engine::reorder; 0 = never). Does not change the trajectories.
  double reorder_interval = 10.0;
  bool debug_overlap = false;  ///< check all pairs for overlap after every event (O(N^2))
  /// Lubachevsky–Stillinger compression, used when the lattice cannot hold the target
  /// diameters: relative diameter growth per unit time, and a collision budget after which
  /// the compression gives up (jammed) with InvalidInput.
  double growth_rate = 0.05;
  std::uint64_t max_compression_collisions = 200000000;
  double compression_stage = 0.5;  ///< time between velocity rescalings while compressing
  /// Coefficient of normal restitution alpha in [0, 1]: 1 is the elastic hard-sphere gas,
  /// below 1 a granular gas (restitution.hpp) that cools. The Lubachevsky–Stillinger
  /// compression of the start is elastic; alpha applies from t = 0 of the run.
  double restitution = 1.0;
  /// TC model of inelastic collapse (Luding & McNamara 1998, restitution.hpp): a collision
  /// is elastic when either particle's previous collision was less than tc_time ago
  /// (>= 0; 0 turns the model off). In the engine's time unit (that of time() and
  /// run_until: sigma sqrt(m/kT0) with the initial kT0 = 1 by default): a fixed time, as the
  /// contact duration of real grains is, not a fraction of the mean free time, which grows
  /// as the gas cools. The default 1e-5 is ~2e-5 of the initial mean free time at packing
  /// 0.1 in 3D and ~4e-4 of it at packing 0.5. Unused while the restitution is 1.
  double tc_time = 1e-5;
  /// Uniform shear flow (lees_edwards.hpp): shear rate a >= 0 per mean collision time of
  /// the ideal gas at the start (1 / nu0, nu0 = D 2^D eta sqrt(kT0 / pi), the Boltzmann
  /// collision frequency at the packing and the temperature kT0 after the start; 0: none).
  /// Lees–Edwards boundaries slide along x (axis 0) with the gradient along y (axis 1);
  /// D >= 2 and at least 4 cells per side. The flow starts at t = 0 of the run.
  double shear_rate = 0.0;
  /// Isokinetic thermostat of the sheared gas: the interval, in mean collision times of the
  /// ideal gas (as shear_rate), between rescalings of the peculiar velocities to kT0
  /// (lees_edwards.hpp); 0: none (the gas heats). Elastic gases only.
  double thermostat_interval = 0.0;
};

}  // namespace hypergas::edmd
