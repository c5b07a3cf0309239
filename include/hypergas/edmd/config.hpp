// hypergas/edmd/config.hpp -- what an event-driven MD run is: N, packing, seed, initial state.
#pragma once

#include <cstddef>
#include <cstdint>

#include "hypergas/initial_state.hpp"

namespace hypergas::edmd {

/// How a particle's prediction chooses the neighbour cells it scans (grids of 3 or more cells
/// per side; Engine::scan). `slab`: the whole 3^D stencil, and a cell crossing keeps the
/// still-valid pair events and scans only the newly adjacent slab of 3^(D-1) cells.
/// `horizon`: every prediction (crossings included) scans only the stencil cells within a
/// contact distance of the box bounding the particle's path until its next cell crossing
/// (0.86 of the 3^D cells in 3D, 0.46 in 6D on average).
/// `filtered` (5 or more cells per side; else as `horizon`): the horizon scan, and a cell,
/// then a particle, is skipped when the box bounding its members' paths (a particle's path
/// until its next crossing; kept per particle and as a union per cell, 8 bits per bound)
/// is farther than a contact distance from the scanner's box. `automatic`: the measured
/// fastest one for D (engine.hpp: slab in D <= 2, horizon in 3D, filtered from 4D). All find
/// every collision; trajectories agree to round-off.
enum class Scan { automatic, slab, horizon, filtered };

/// Parameters of an EDMD run. Units: sigma (diameter of species 0) = 1, m (mass of species
/// 0) = 1, kT = init_params.kT (default 1); time in sigma sqrt(m/kT).
struct Config {
  std::size_t n = 1000;       ///< number of particles (>= 2)
  double packing = 0.1;       ///< target packing fraction eta = sum_i v_D(sigma_i/2) / L^D
  std::uint64_t seed = 1;     ///< seed of the positions and velocities
  InitialState init = InitialState::maxwell;  ///< initial velocity state (initial_state.hpp)
  InitialParams init_params{};  ///< kT, mixture fraction and mass ratio of the state
  double size_ratio = 1.0;    ///< radii scenes: diameter of population 1 (the last
                              ///< round(fraction n) particles) over that of population 0
  /// Collisions per particle between renumberings of the particles by position (memory
  /// locality, Engine::reorder; 0 = never). Does not change the trajectories.
  double reorder_interval = 10.0;
  Scan scan = Scan::automatic;  ///< neighbour-cell choice of a prediction (see Scan)
  bool debug_overlap = false;  ///< check all pairs for overlap after every event (O(N^2))
  /// Lubachevsky–Stillinger compression, used when the lattice cannot hold the target
  /// diameters: relative diameter growth per unit time, and a collision budget after which
  /// the compression gives up (jammed) with InvalidInput.
  double growth_rate = 0.05;
  std::uint64_t max_compression_collisions = 200000000;
  double compression_stage = 0.5;  ///< time between velocity rescalings while compressing
};

}  // namespace hypergas::edmd
