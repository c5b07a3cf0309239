// hypergas/observer.hpp -- how engines hand snapshots to analysis and output.
//
// Engines are templates on D; analysis is compiled once and works on a runtime dimension.
// A `Snapshot` is a const, non-owning view of the state at one instant, with the dimension
// and strides as runtime values, so the compiled analysis library reads any engine's state
// without reaching into it. Observers are the only virtual interface on the data path and
// are called once per sampling interval, never per collision. What an analysis needs per
// collision it asks the engine to keep in a tally (hypergas/tally/tally.hpp), through
// Snapshot::tally: the engine's collision-level observer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

#include "hypergas/particles.hpp"

namespace hypergas {

namespace tally {
struct Slot;
struct ContactSlot;
}

/// A read-only view of the particles at one instant. Arrays are valid only during the
/// observer call. Velocity of particle i, component k: velocities[i * stride + k].
struct Snapshot {
  int dim = 0;        ///< D
  std::size_t n = 0;  ///< number of particles
  int stride = 0;     ///< doubles per particle in velocities / positions
  double time = 0.0;  ///< engine time (DSMC: mean collision times; EDMD: sigma sqrt(m/kT))
  double collisions_per_particle = 0.0;  ///< 2 * collisions / n so far
  std::uint64_t collisions = 0;          ///< total accepted collisions so far
  const double* velocities = nullptr;
  const double* positions = nullptr;         ///< unwrapped positions, or nullptr (velocity space)
  const double* inv_mass = nullptr;          ///< per-particle inverse mass, or nullptr
  const std::uint8_t* species = nullptr;     ///< per-particle species, or nullptr (one species)
  const double* species_inv_mass = nullptr;  ///< inverse mass per species (with `species`)
  int n_species = 1;
  /// The engine's tally slot (engines that keep one: DSMC), or nullptr. An observer may
  /// install a tally built from this snapshot; the engine then applies every later
  /// collision to it (tally/tally.hpp).
  tally::Slot* tally = nullptr;
  /// The EDMD engine's slot for a Helfand tally (tally/helfand.hpp), or nullptr: an
  /// observer may install one, which every later collision then updates.
  tally::ContactSlot* contacts = nullptr;
  /// Side of the periodic box (length units), or 0 (velocity space).
  double box = 0.0;
  /// The velocities are the true ones divided by exp(log_velocity_scale): a freely cooling
  /// granular gas in the DSMC engine keeps them at its initial temperature
  /// (dsmc/granular.hpp); 0 for every other state.
  double log_velocity_scale = 0.0;
  /// Time in the unit of the initial temperature (DSMC: mean collision times at kT0), or
  /// NaN when it is `time` (every engine whose clock is not rescaled).
  double real_time = std::numeric_limits<double>::quiet_NaN();

  /// Inverse mass of particle i (1 for a single unit-mass species).
  double inverse_mass(std::size_t i) const {
    if (inv_mass) return inv_mass[i];
    if (species) return species_inv_mass[species[i]];
    return 1.0;
  }
};

/// Receives snapshots at the sampling times of a run.
class Observer {
 public:
  virtual ~Observer() = default;
  virtual void observe(const Snapshot& s) = 0;
};

/// Builds the velocity part of a snapshot of `p` (positions, time and counters are the
/// engine's to fill in).
template <int D, Features F>
Snapshot make_snapshot(const Particles<D, F>& p) {
  Snapshot s;
  s.dim = D;
  s.n = p.size();
  s.stride = Particles<D, F>::stride;
  s.velocities = p.velocity_data().data() + Particles<D, F>::velocity_offset;
  return s;
}

}  // namespace hypergas
