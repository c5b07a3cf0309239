// hypergas/analysis/helfand_recorder.hpp -- shear viscosity, thermal conductivity and
// self-diffusion of the event-driven hard-sphere fluid, by the Einstein-Helfand route and
// by Green-Kubo from the same fluxes, with their kinetic and collisional parts.
//
// The recorder is an Observer on the EDMD run's snapshots. At its first snapshot at or
// after `start` it measures the mean free time tau so far (collisions per particle over the
// time), fixes a grid of spacing dt tau, and makes a Helfand tally that it shares with the
// engine (Observer::request; tally/helfand.hpp), which every later collision updates. Each snapshot drains the grid
// intervals closed since the last one into a BlockCorrelator (correlator.hpp) and renews
// the tally's kinetic sums from the velocities. Units: sigma = m = 1, kT = 2 E / (D (N - 1))
// (zero total momentum), volume V = L^D. Per grid interval h = dt tau the series are
//   stress:  (G_ab(t + h) - G_ab(t)) / h, a != b and the halves of consecutive diagonal
//            differences, split into kinetic (int K dt) and collisional (sum dp r) parts;
//   heat:    the same for the energy moment;
//   the instantaneous kinetic stress K at the grid points (a second, independent route to
//   the kinetic part); the velocities of `tagged` particles at the grid points, and their
//   exact displacements over each interval.
// Results (transport.csv):
//   viscosity / thermal_conductivity: the Einstein-Helfand slope, eta = lim
//     <(G(t) - G(0))^2> / (2 V kT t), lambda = the same / kT^2: the least-squares slope of the
//     mean square Helfand moment over t in [2 t_c, 4 t_c] (within the lags), computed from
//     the increments' correlations c(l), MSD(n) = h^2 (n c(0) + 2 sum_{l<n} (n - l) c(l)),
//     which is the average over every origin of the direct mean square;
//   *_green_kubo: int C dt = h (c(0)/2 + sum_{l=1}^{cut} c(l)) + geometric tail (exact for
//     interval averages), the cut t_c at `window` integral times of the kinetic part but
//     at least 5 mean free times (a dense fluid's collisional stress relaxes more slowly)
//     and at most a quarter of the lags;
//   *_kinetic, *_cross, *_collisional: the same sum of the kinetic, and collisional
//     correlations, the cross part the total minus both;
//   *_kinetic_point: the kinetic part by the trapezoid rule (with end corrections) on the
//     point samples of K, checking the tally's time integration;
//   self_diffusion: Green-Kubo of the tagged velocities; self_diffusion_einstein: the slope
//     of their exact mean square displacements; in 3D also self_diffusion_yeh_hummer, the
//     infinite-system value D + xi kT / (6 pi eta L), xi = 2.837297 (Yeh & Hummer, J. Phys.
//     Chem. B 108, 15873 (2004)).
// Errors: the same estimators in each of the correlator's error stretches. Every row gives
// the first Sonine dilute value and the Enskog value (analysis/enskog.hpp) with
// chi = g(sigma+) from the collision rate measured over the recording (nu / nu_B).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "hypergas/analysis/correlator.hpp"
#include "hypergas/analysis/transport_recorder.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/tally/helfand.hpp"

namespace hypergas::analysis {

class HelfandRecorder final : public Observer {
 public:
  /// A recorder for a D-dimensional one-species gas of n particles that samples from the
  /// first snapshot at or after `start` to `end` (engine time). s.dt and s.max_lag are in
  /// mean free times; s.warmup is not used (`start` replaces it). Throws InvalidInput on
  /// bad settings.
  HelfandRecorder(const TransportSettings& s, int dim, std::size_t n, double start, double end);

  void observe(const Snapshot& s) override;
  /// Asks the engine to keep the Helfand tally made at the first sample (once).
  void request(tally::Requests& r) override;
  /// Grid intervals recorded so far.
  std::uint64_t frames() const { return corr_ ? corr_->frames() : 0; }
  /// Computes the coefficients (once, after the run).
  const std::vector<TransportCoefficient>& finish();
  /// Grid spacing (engine time; 0 before the first sample) and the mean free time it was
  /// made from.
  double dt() const { return h_; }
  double mean_free_time() const { return tau_; }
  double kT() const { return kT_; }
  /// g(sigma+) from the collision rate over the recording, and the packing fraction.
  double chi() const { return chi_; }
  double packing() const { return phi_; }
  /// transport.csv (the DSMC recorder's columns; values in sigma, m, kT units).
  void write_transport_csv(const std::string& path) const;
  /// correlations.csv: time and the normalised correlations of the total stress and heat
  /// interval fluxes and the tagged velocities, and the mean square Helfand moments over
  /// 2 V kT t (2 V kT^2 t) and the mean square displacement over 2 D t.
  void write_correlations_csv(const std::string& path) const;

 private:
  void install(const Snapshot& s);

  TransportSettings set_;
  int dim_;
  std::size_t n_;
  double start_, end_;
  double kT_ = 0.0, tau_ = 0.0, h_ = 0.0, volume_ = 0.0, t_first_ = 0.0, t_last_ = 0.0;
  double chi_ = 0.0, phi_ = 0.0;
  std::uint64_t coll_first_ = 0, coll_last_ = 0;
  std::vector<std::uint32_t> tagged_;
  std::unique_ptr<BlockCorrelator> corr_;
  std::shared_ptr<tally::Helfand> tally_;  // updated by the engine, read here
  bool installed_ = false;                 // the engine was asked to keep tally_
  std::vector<double> frame_;
  std::vector<std::vector<double>> curves_;
  std::vector<TransportCoefficient> result_;
};

}  // namespace hypergas::analysis
