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
};

}  // namespace hypergas::edmd
