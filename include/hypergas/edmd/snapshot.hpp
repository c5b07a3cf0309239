// hypergas/edmd/snapshot.hpp -- the EDMD state as an observer sees it: a Snapshot at one
// instant in the original numbering of the particles.
//
// The engine renumbers its particles from time to time (Engine::reorder) and lets each
// particle's record lag behind at its own clock; a snapshot undoes both. It builds one
// buffer of [unwrapped position, velocity] records (2 D doubles per particle) in the
// original numbering and, for mixtures, the species in the same order, and reads the
// particle store without copying it.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "hypergas/edmd/lees_edwards.hpp"
#include "hypergas/edmd/observables.hpp"
#include "hypergas/edmd/state.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/tally/helfand.hpp"

namespace hypergas::edmd {

/// What a snapshot of a sheared gas adds (Engine::sample_sheared): the stress sums
/// (Snapshot::stress_integral, kinetic_integral, kinetic_stress), the time in ideal-gas mean
/// collision times, and the flow (its kT0, and the velocity LeesEdwards::stream that the
/// velocities lose to become peculiar).
template <int D>
struct ShearView {
  const double* stress_integral;
  const double* kinetic_integral;
  const double* kinetic_stress;
  double real_time;
  const LeesEdwards<D>* flow;
};

/// Calls obs with the state `s` at time ts (>= every local clock), in the original
/// numbering (State::slot), positions unwrapped by the periodic image counts: the first
/// obs.particles_read() particles (all by default). Changes
/// nothing but `contacts`, the engine's Helfand slot, which receives what obs requests.
template <int D, Features F>
void observe_state(const State<D, F>& s, double ts, Observer& obs,
                   tally::ContactSlot* contacts = nullptr,
                   const MeasurementWindow* window = nullptr,
                   const ShearView<D>* shear = nullptr) {
  const std::size_t n = std::min(s.size(), obs.particles_read());
  constexpr int st = 2 * D;
  std::vector<double> rec(n * st);
  for (std::size_t a = 0; a < n; ++a) {  // a: original id, i: its current slot
    const std::size_t i = s.slot[a];
    for (int k = 0; k < D; ++k) {
      rec[a * st + k] = s.p.position(i)[k] + s.p.velocity(i)[k] * (ts - s.p.local_time(i)) +
                        s.L * s.image[i * D + k];
      rec[a * st + D + k] = s.p.velocity(i)[k];
    }
    if (shear) {  // peculiar velocity: the flow at the particle's height in the box
      constexpr int y = LeesEdwards<D>::y;
      rec[a * st + D] -= shear->flow->stream(s.p.position(i)[y] +
                                             s.p.velocity(i)[y] * (ts - s.p.local_time(i)));
    }
  }
  Snapshot snap;
  snap.dim = D;
  snap.n = n;
  snap.stride = st;
  snap.velocities = rec.data() + D;
  snap.positions = rec.data();
  snap.time = ts;
  snap.box = s.L;
  snap.contacts = contacts;
  if (window) {
    snap.window_start = window->t0;
    snap.window_virial = window->virial;
    snap.window_collisions = window->collisions(s.ncoll);
  }
  if (shear) {
    snap.stress_integral = shear->stress_integral;
    snap.kinetic_integral = shear->kinetic_integral;
    snap.kinetic_stress = shear->kinetic_stress;
    snap.shear_kT0 = shear->flow->kT0;
    snap.real_time = shear->real_time;
  }
  snap.collisions = s.ncoll;
  snap.collisions_per_particle =
      2.0 * static_cast<double>(s.ncoll) / static_cast<double>(s.size());
  std::vector<std::uint8_t> species;
  std::array<double, max_species> species_w{};
  if constexpr (F.species) {
    species.resize(n);
    int ns = 1;
    for (std::size_t a = 0; a < n; ++a) {
      species[a] = static_cast<std::uint8_t>(s.p.species(s.slot[a]));
      ns = std::max(ns, species[a] + 1);
    }
    for (int k = 0; k < max_species; ++k) species_w[k] = s.p.species_inv_mass(k);
    snap.species = species.data();
    snap.species_inv_mass = species_w.data();
    snap.n_species = ns;
  }
  obs.observe(snap);
  tally::Requests r;
  obs.request(r);
  if (contacts) contacts->apply(r);
}

}  // namespace hypergas::edmd
