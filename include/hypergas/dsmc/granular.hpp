// hypergas/dsmc/granular.hpp -- granular gases in the DSMC engine: inelastic collisions, the
// homogeneous cooling state in scaled velocities, and the white-noise drive.
//
// Restitution. With a coefficient of normal restitution alpha the change of relative
// velocity that the collision model produces is scaled by (1 + alpha) / 2 (apply_deflection,
// dsmc/update.hpp):
// for hard spheres g' = g - (1 + alpha) (g.n) n, so the normal relative velocity is
// reversed and multiplied by alpha; momentum is conserved and the pair loses
// (1 - alpha^2) / 2 mu (g.n)^2 (mu the reduced mass). For the isotropic models (maxwell,
// vhs) n is the implied normal (g - g')/|g - g'| of the elastic scattering: the same rule,
// the inelastic form of those models. alpha = 1 multiplies by nothing: the elastic engine.
//
// The homogeneous cooling state (HCS, no drive). The gas cools without bound (Haff's law),
// and a run in plain velocities would lose its precision: the rounding of the momentum
// sums stays at the size of the early velocities while the thermal speed falls, and the
// speeds end as subnormal numbers. The engine therefore stores v / scale and renormalises
// the stored velocities to the initial temperature kT0 every N candidates (about half a
// collision per particle): a pass finds the stored kT and mean velocity, the next
// subtracts the mean velocity, multiplies by f = sqrt(kT0 / kT) and sets the majorant;
// scale is divided by f. The mean velocity is zero in exact arithmetic (the start has zero
// momentum and collisions keep it); what rounding leaves of it would otherwise stay
// while the thermal speed falls (it grows as sqrt(T0 / T) against it: 4e-4 of the
// thermal momentum after T/T0 = 1e-27, measured), so it is removed. The
// process of the stored velocities is the Kac process with the rate constant of kT0, so
// the engine's clock (time()) runs at the collision rate of the scaled gas: a unit of
// time is a mean collision time at the temperature of the moment, to within the cooling
// between renormalisations (at most a few per cent of the rate). The rate of a pair in
// real time is c |scale g|^a, so real time advances by dtime / scale^a: real_time() is
// the time in mean collision times at kT0, the clock of Haff's law
// T(t) = T0 / (1 + t / t0)^2. The temperature is kT = scale^2 kT(stored).
//
// The white-noise drive (hard spheres). Every particle receives the velocity kick
// sqrt(xi2 drive_dt) N(0, 1) per component at the times (k + 1/2) drive_dt of the engine's
// clock (midway between the multiples of drive_dt, where samples usually fall: there the
// temperature's sawtooth between kicks is at its mean to first order in drive_dt);
// the mass-weighted mean kick is subtracted, so the total momentum stays zero. xi2 is
// chosen so that the first Sonine energy balance holds at kT0: the energy put in per
// particle and unit time, D xi2 / 2 (unit mass), equals the loss zeta kT0 D / 2 with
// zeta the cooling rate of granular/theory.hpp at the driven state's a2. The kicks split
// the diffusion from the collisions (first order in drive_dt: docs/validation.md). The
// driven gas is stationary: no renormalisation, and real_time() = time().
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/detail/state.hpp"
#include "hypergas/granular/theory.hpp"

namespace hypergas::dsmc::detail {

/// The engine's stream of kick number k (independent of every other stream of the seed).
inline Rng kick_stream(std::uint64_t seed, std::uint64_t k) { return Rng(seed).split(7).split(k); }

/// Whether the gas cools freely (restitution < 1, no drive): renormalised velocities.
template <int D, class Model, Features F>
bool cooling(const State<D, Model, F>& s) {
  return s.impulse != 1.0 && s.cfg.drive == Drive::none;
}

/// Renormalises the stored velocities of a cooling gas to kT0 (see the file comment) and
/// sets the majorant; the candidate count since the last scan restarts. `record`: the
/// factor goes into log_scale (false: a gas whose energy is held, where it is 1 to
/// rounding: the sheared gas under the isokinetic thermostat, dsmc/shear.hpp).
template <int D, class Model, Features F>
void renormalise(State<D, Model, F>& s, bool record = true) {
  constexpr int S = State<D, Model, F>::stride;
  double* v = s.p.velocity_data().data();
  const std::size_t n = s.p.size();
  double e2 = 0.0, mass = 0.0, mom[D] = {};
  for (std::size_t i = 0; i < n; ++i) {
    const double m = s.p.mass(i);
    double u = 0.0;
    for (int k = 0; k < D; ++k) {
      u += v[i * S + k] * v[i * S + k];
      mom[k] += m * v[i * S + k];
    }
    e2 += u * m;
    mass += m;
  }
  double w[D];
  for (int k = 0; k < D; ++k) {
    w[k] = mom[k] / mass;
    e2 -= mass * w[k] * w[k];
  }
  const double kT = e2 / (D * (static_cast<double>(n) - 1.0));
  double m2 = 0.0;
  if (kT > 0.0 && std::isfinite(kT)) {
    const double f = std::sqrt(s.kT0 / kT);
    for (std::size_t i = 0; i < n; ++i) {
      double u = 0.0;
      for (int k = 0; k < D; ++k) {
        v[i * S + k] = (v[i * S + k] - w[k]) * f;
        u += v[i * S + k] * v[i * S + k];
      }
      m2 = std::max(m2, u);
    }
    if (record) s.log_scale -= std::log(f);
  }
  s.bound.set(m2);
  s.since_scan = 0;
}

/// The white-noise strength xi2 (velocity^2 per unit time, unit mass) of the drive.
template <int D, class Model, Features F>
double drive_strength(const State<D, Model, F>& s) {
  const double alpha = 2.0 * s.impulse - 1.0;
  return granular::cooling_rate(alpha, D, granular::a2_white_noise(alpha, D)) * s.kT0;
}

/// Kick number s.kicks + 1 of the white-noise drive: every velocity gets
/// sqrt(xi2 drive_dt) N(0, 1) per component, less the mass-weighted mean kick; then the
/// majorant is set from the new speeds.
template <int D, class Model, Features F>
void kick(State<D, Model, F>& s) {
  constexpr int S = State<D, Model, F>::stride;
  ++s.kicks;
  Rng r = kick_stream(s.cfg.seed, s.kicks);
  const double a = std::sqrt(drive_strength(s) * s.cfg.drive_dt);
  double* v = s.p.velocity_data().data();
  const std::size_t n = s.p.size();
  double mom[D] = {};
  double mass = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double m = s.p.mass(i);
    mass += m;
    for (int k = 0; k < D; ++k) {
      const double dv = a * r.normal();
      v[i * S + k] += dv;
      mom[k] += m * dv;
    }
  }
  double m2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double u = 0.0;
    for (int k = 0; k < D; ++k) {
      v[i * S + k] -= mom[k] / mass;
      u += v[i * S + k] * v[i * S + k];
    }
    m2 = std::max(m2, u);
  }
  s.bound.set(m2);
  s.since_scan = 0;
}

/// Time of the next kick ((kicks + 1/2) drive_dt), or +infinity without a drive.
template <int D, class Model, Features F>
double next_kick(const State<D, Model, F>& s) {
  if (s.cfg.drive == Drive::none) return HUGE_VAL;
  return (static_cast<double>(s.kicks) + 0.5) * s.cfg.drive_dt;
}

/// Before an epoch or step: the renormalisation of a cooling gas when it is due.
template <int D, class Model, Features F>
void granular_upkeep(State<D, Model, F>& s) {
  if (cooling(s) && s.since_scan >= s.n) renormalise(s);
}

/// After an epoch or step that moved the clock from t0 to s.time: real time of a cooling
/// gas; a kick when the clock reached the next one.
template <int D, class Model, Features F>
void granular_after(State<D, Model, F>& s, double t0) {
  if (cooling(s)) {
    const double a = s.model.exponent();
    s.real_time += (s.time - t0) * std::exp(-a * s.log_scale);
  }
  if (s.cfg.drive != Drive::none && s.time >= next_kick(s)) kick(s);
}

}  // namespace hypergas::dsmc::detail
