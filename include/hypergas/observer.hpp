// hypergas/observer.hpp -- how engines hand snapshots to analysis and output.
//
// Engines are templates on D; analysis is compiled once and works on a runtime dimension.
// A `Snapshot` is a const, non-owning view of the state at one instant, with the dimension
// and strides as runtime values, so the compiled analysis library reads any engine's state
// without reaching into it. Observers are the only virtual interface on the data path and
// are called once per sampling interval, never per collision. What an analysis needs per
// collision it asks the engine to keep (a tally, collective fluxes, a Helfand tally) through
// Observer::request, which the engine calls right after observe and applies before it moves
// on: a snapshot is never written through, and what an observer wants from the engine is a
// request, not a write into the engine.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "hypergas/particles.hpp"

namespace hypergas {

namespace tally {
struct Slot;
struct ContactSlot;
struct Requests;
}

/// A read-only view of the particles at one instant. Arrays are valid only during the
/// observer call. Velocity of particle i, component k: velocities[i * stride + k].
struct Snapshot {
  int dim = 0;        ///< D
  /// Number of particles in the snapshot: all of them, or, where the engine builds the
  /// snapshot as a copy (EDMD), the first Observer::particles_read() in its numbering.
  std::size_t n = 0;
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
  /// What the engine keeps per collision (engines that keep a tally: DSMC), or nullptr. An
  /// observer asks for a tally or fluxes in Observer::request; the engine then applies every
  /// later collision to them (tally/tally.hpp).
  const tally::Slot* tally = nullptr;
  /// The EDMD engine's Helfand slot (tally/helfand.hpp), or nullptr: an observer asks for a
  /// Helfand tally in Observer::request, which every later collision then updates.
  const tally::ContactSlot* contacts = nullptr;
  /// Side of the periodic box (length units), or 0 (velocity space).
  double box = 0.0;
  /// EDMD: the engine's measurement window (pressure_Z, collision_rate): its start time, the
  /// collision virial sum r_ij . dp_i and the collisions since then; NaN and 0 elsewhere.
  /// Two snapshots of one window give Z and the collision rate between them.
  double window_start = std::numeric_limits<double>::quiet_NaN();
  double window_virial = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t window_collisions = 0;
  /// The velocities are the true ones divided by exp(log_velocity_scale): a freely cooling
  /// granular gas in the DSMC engine keeps them at its initial temperature
  /// (dsmc/granular.hpp); 0 for every other state.
  double log_velocity_scale = 0.0;
  /// Time in the unit of the initial temperature (DSMC: mean collision times at kT0), or
  /// NaN when it is `time` (every engine whose clock is not rescaled).
  double real_time = std::numeric_limits<double>::quiet_NaN();
  /// A sheared EDMD gas (edmd/lees_edwards.hpp; nullptr elsewhere): `velocities` are the
  /// peculiar ones (the flow's velocity at each particle subtracted), stress_integral is the
  /// D x D row-major int sum m c c^T dt + sum_coll r dp^T since the shear started (divided
  /// by the volume and a time interval: the pressure tensor over that interval),
  /// kinetic_integral its kinetic part int sum m c c^T dt alone, and kinetic_stress the
  /// current sum m c c^T; shear_kT0 is the temperature at the start.
  const double* stress_integral = nullptr;
  const double* kinetic_integral = nullptr;
  const double* kinetic_stress = nullptr;
  double shear_kT0 = std::numeric_limits<double>::quiet_NaN();

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
  /// Called by the engine right after observe(s): adds to `r` what this observer wants the
  /// engine to keep from now on (tally/tally.hpp: Requests); the engine applies `r` once
  /// every observer of the snapshot has returned. Asks for nothing by default.
  virtual void request(tally::Requests& r) { (void)r; }
  /// How many particles, the first ones in the engine's original numbering, this observer
  /// reads: an engine that copies the state to build a snapshot (EDMD) may copy only these
  /// (Snapshot::n). All of them by default.
  virtual std::size_t particles_read() const { return std::numeric_limits<std::size_t>::max(); }
};

/// Hands each snapshot, and then each request, to `targets` in order.
class FanOut final : public Observer {
 public:
  explicit FanOut(std::vector<Observer*> targets) : targets_(std::move(targets)) {}
  void observe(const Snapshot& s) override {
    for (Observer* t : targets_) t->observe(s);
  }
  void request(tally::Requests& r) override {
    for (Observer* t : targets_) t->request(r);
  }
  std::size_t particles_read() const override {
    std::size_t n = 0;
    for (const Observer* t : targets_) n = std::max(n, t->particles_read());
    return n;
  }
  bool empty() const { return targets_.empty(); }

 private:
  std::vector<Observer*> targets_;
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
