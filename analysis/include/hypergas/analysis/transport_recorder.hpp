// hypergas/analysis/transport_recorder.hpp -- Green-Kubo transport coefficients of the
// Boltzmann gas from the equilibrium fluctuations of the velocity-space (DSMC) engine.
//
// The recorder is an Observer called on a fine grid of instants (spacing dt). At its first
// snapshot at or after `warmup` it makes collective fluxes and asks the engine to keep them
// (Observer::request; hypergas/tally/fluxes.hpp), and every later collision updates them
// exactly; each snapshot
// then reads them, and the velocities of `tagged` particles, into a BlockCorrelator
// (correlator.hpp). Units: the engine's, m = 1 (one species), kT = sum |v|^2 / (D (N - 1))
// (conserved; dsmc/time_unit.hpp), time in equilibrium mean collision times tau. With
// N particles in a volume V (n = N / V), the Green-Kubo integrals give
//   viscosity             eta    = (n / kT)   int_0^inf (1/N) <J_ab(t) J_ab(0)> dt,
//                         J_ab = sum_i m v_ia v_ib (a != b) and (J_aa - J_bb) / 2;
//   thermal conductivity  lambda = (n / kT^2) int_0^inf (1/N) <J_qa(t) J_qa(0)> dt,
//                         J_qa = sum_i v_ia (m |v_i|^2 / 2 - (D + 2) kT / 2);
//   self-diffusion        D_s    = (1 / D) int_0^inf <v_i(t) . v_i(0)> dt (tagged particles),
//                         and in the Einstein form, the growth of the mean square of exact
//                         virtual displacements x_i = int v_i dt (tally/fluxes.hpp: the
//                         times of a tagged particle's collisions within an epoch are drawn
//                         from their exact law), self_diffusion_einstein.
// They are reported reduced, as pure numbers: eta* = eta / (n kT tau),
// lambda* = lambda / (n k_B (kT / m) tau), D* = D_s / ((kT / m) tau); each averaged over
// all components (the D (D - 1) / 2 off-diagonal stresses and the D - 1 differences of
// consecutive diagonal ones, the D heat-flux components, the D components of every tagged
// velocity). The series are scaled so that each group's correlation is directly the reduced
// integrand: J / (sqrt(N) kT), J_q / (sqrt(N) kT^(3/2)), v / sqrt(kT).
//
// Each integral I(t) = int_0^t C is the trapezoid rule on the grid. Its cut: the first lag
// t_c with t_c >= window * I(t_c) / C(0) (an automatic window at `window` integral times,
// after Sokal), or the largest lag if none; the Euler-Maclaurin end corrections
// h^2/12 (C'(0+) - C'(t_c)) and the tail beyond the cut, C(t_c) / g with g the decay rate
// of ln C over [t_c / 2, t_c] on the whole run (C(0) / I(t_c) if that fit fails), are
// added; the tail's size is reported. Errors: the same cut, g and corrections in each of
// the correlator's error stretches; the standard error of the mean over stretches. The decay rate: a least-squares line through
// ln C(t) over t <= 1.5 I / C(0) (C above ~e^-1.5 of C(0)), per stretch for its error.
//
// References (docs/validation.md derives them): the first Sonine (Chapman-Enskog)
// approximations of hard spheres in D dimensions, eta* = (D + 2)/4, lambda* = D (D + 2)^2 /
// (8 (D - 1)), D* = D/2; isotropic scattering at rate ~ |g|^a (vhs; maxwell a = 0),
// eta* = 2 D (D + 2) / ((D + a)(D + a + 2)), lambda* = D (D + 2) / (2 (D - 1)) eta*,
// D* = 2 D / (D + a). For Maxwell molecules these are exact, and the correlations decay
// exactly exponentially in the N-particle process, at rates N / (N - 1) times 1/2 (stress,
// tagged velocity) and (D - 1) / (2 D) (heat flux).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hypergas/analysis/correlator.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/tally/fluxes.hpp"

namespace hypergas::analysis {

/// What a transport run measures and how.
struct TransportSettings {
  double dt = 0.05;         ///< grid spacing of the samples (mean collision times)
  double max_lag = 40.0;    ///< longest lag of the correlations (mean collision times)
  int tagged = 32;          ///< tagged particles for self-diffusion (at most N; 0: no
                            ///< self-diffusion rows, as the lanes scheme needs)
  double warmup = 20.0;     ///< time before the first sample (relaxation of the start)
  double window = 3.0;      ///< integral times up to the cut (see the file comment)
  int error_blocks = 32;    ///< stretches for the standard errors
  std::uint64_t seed = 1;   ///< the tagged collisions' times within an epoch (own stream)
};

/// One reduced transport coefficient.
struct TransportCoefficient {
  std::string name;         ///< viscosity, thermal_conductivity, self_diffusion
  double value = 0.0;       ///< reduced Green-Kubo integral, tail included
  double error = 0.0;       ///< its standard error
  double sonine = 0.0;      ///< the first Sonine (Chapman-Enskog) value, reduced
  double ratio = 0.0;       ///< value / sonine
  double ratio_error = 0.0;
  double c0 = 0.0;          ///< C(0)
  double t_cut = 0.0;       ///< the cut (mean collision times)
  double tail = 0.0;        ///< the tail estimate included in value
  double rate = 0.0;        ///< fitted decay rate of C (1 / mean collision times)
  double rate_error = 0.0;
  double sonine_rate = 0.0; ///< C(0) / sonine with C(0) of the Maxwellian (1 or (D+2)/2)
  double enskog = 0.0;      ///< Enskog's value (analysis/enskog.hpp; the dilute gas: sonine)
  double enskog_ratio = 0.0;
  double enskog_ratio_error = 0.0;
  std::vector<double> stretches;  ///< the value from each error stretch
  /// The parts of `error` where the estimator states them (EDMD: the plateau rule,
  /// integrals.hpp): the standard error over the stretches and the measured truncation
  /// error of the cut, error = sqrt(statistical^2 + truncation^2); NaN where `error` is
  /// statistical only (DSMC, whose correlations decay exponentially: the tail is fitted).
  double statistical_error = std::numeric_limits<double>::quiet_NaN();
  double truncation_error = std::numeric_limits<double>::quiet_NaN();
};

/// Writes transport.csv: one row per coefficient, header coefficient, value, error,
/// first_sonine, ratio, ratio_error, t_cut, tail, c0, decay_rate, decay_rate_error,
/// first_sonine_rate, enskog, enskog_ratio, enskog_ratio_error, statistical_error,
/// truncation_error (empty where not finite).
/// Both engines' recorders write it.
void write_transport_rows(const std::string& path, const std::vector<TransportCoefficient>& rows);

/// What the first Sonine values need to know of a DSMC collision model (the model type's
/// exponent() and isotropic_scattering, dsmc/models.hpp; registry::model_traits by name):
/// the exponent a of its pair rate |g|^a and its law of scattering, isotropic (Maxwell
/// molecules a = 0, VHS) or specular at a hard-sphere normal (hard spheres, a = 1).
struct CollisionLaw {
  double exponent = 1.0;
  bool isotropic_scattering = false;
};

/// The reduced first Sonine values of a gas with collision law `law` in D dimensions:
/// {eta*, lambda*, D*}. Throws InvalidInput for D < 2 and for hard-sphere scattering with
/// a rate exponent other than 1.
std::vector<double> first_sonine(const CollisionLaw& law, int dim);

/// The converged Chapman-Enskog value over the first Sonine one where a published value
/// exists: hard spheres in 3D, viscosity 1.016034 and thermal conductivity 1.025218
/// (Pekeris & Alterman, Proc. Natl. Acad. Sci. USA 43, 998 (1957)); NaN elsewhere (Maxwell
/// molecules need none: their first Sonine values are exact).
double converged_over_sonine(const CollisionLaw& law, int dim, const std::string& name);

class TransportRecorder final : public Observer {
 public:
  /// A recorder for a D-dimensional one-species gas of n particles, `frames` planned
  /// samples from the first at or after s.warmup. Throws InvalidInput on bad settings.
  TransportRecorder(const TransportSettings& s, int dim, std::size_t n, std::uint64_t frames,
                    CollisionLaw law);

  void observe(const Snapshot& s) override;
  /// Asks the engine to keep the fluxes made at the first sample (tally/fluxes.hpp).
  void request(tally::Requests& r) override;
  /// Samples taken so far.
  std::uint64_t frames() const { return corr_.frames(); }
  /// Computes the coefficients (call once, after the run; more samples cannot follow).
  const std::vector<TransportCoefficient>& finish();
  /// The normalised correlation C_g(t) / C_g(0) of group g (0 viscosity, 1 conductivity,
  /// 2 self-diffusion), after finish().
  std::vector<double> normalised(int g) const;
  double dt() const { return set_.dt; }
  double kT() const { return kT_; }
  /// transport.csv (write_transport_rows; reduced values, Enskog = the first Sonine value).
  void write_transport_csv(const std::string& path) const;
  /// correlations.csv: time and each normalised correlation, with the first Sonine
  /// exponential exp(-t C(0) / sonine) beside each.
  void write_correlations_csv(const std::string& path) const;

 private:
  TransportSettings set_;
  int dim_;
  std::size_t n_;
  CollisionLaw law_;
  std::vector<std::size_t> tagged_;
  BlockCorrelator corr_;
  double kT_ = 0.0;
  std::vector<double> frame_, last_x_;
  std::vector<std::vector<double>> curves_;
  std::vector<TransportCoefficient> result_;
  std::unique_ptr<tally::Fluxes> pending_;  // made from a snapshot, for the engine to keep
};

}  // namespace hypergas::analysis
