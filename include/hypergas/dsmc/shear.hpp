// hypergas/dsmc/shear.hpp -- uniform shear flow in the DSMC engine: the exact Kac process of
// the peculiar velocities V of a gas with the flow u_x = a y (docs/validation.md, "Uniform
// shear flow").
//
// In the frame that moves with the flow the gas is spatially homogeneous and the peculiar
// velocities obey, between collisions,
//   dV/dt = -a V_y e_x - zeta V,
// with zeta = 0 (thermostat none: viscous heating) or the Gaussian (isokinetic) thermostat
// zeta = -a sum m V_x V_y / sum m V^2, which holds the kinetic energy fixed. The flow is
// linear and the same for every particle, so the engine stores reference velocities W and
// one map for all of them: V = lam S(sig) W, where S(sig) W = W - sig W_y e_x is the shear
// accumulated since the segment began (sig = a (t - t0)) and lam the thermostat's factor.
// No particle moves between collisions, and nothing is stepped: a collision reads the two
// true velocities through the map, collides them with the engine's kernel (collide_pair,
// every model, species and restitution) and stores them back through the inverse map.
//
// The thermostat's factor is exact too: the energy sum m |V|^2 = lam^2 Q(sig) with
// Q(sig) = A - 2 sig B + sig^2 C (A = sum m |W|^2, B = sum m W_x W_y, C = sum m W_y^2) stays
// at its value E0 between collisions, so lam = sqrt(E0 / Q(sig)); an elastic collision keeps
// sum m |V|^2 and changes A, B and C by its two particles (updated as it happens). Then
// dV/dt = (lam'/lam) V - a V_y e_x, which is the flow with zeta = -lam'/lam.
//
// Candidates. The pair rate c |g|^a_m / (N - 1) (a_m the model's exponent) depends on the
// true relative velocity g = lam S (W_i - W_j), which changes with time, so candidates carry
// their times: a Poisson process of rate Lambda = N c G^a_m / 2 drawn by exponential
// waiting times (the epochs' stream), where G bounds |g| over the segment: |S(sig)| <=
// (sig + sqrt(sig^2 + 4)) / 2 (the spectral norm of the 2 x 2 shear), lam <= its maximum
// over the rest of the segment (Q is a convex quadratic), and |W_i - W_j| <= the speed
// bound of the stored W (majorant.hpp). After an accepted collision the bound is checked
// and raised if needed; the process restarts with the new rate at that stopping time. A
// candidate at time t is accepted with probability (|g(t)| / G)^a_m (thinning). Candidate K
// draws its pair, acceptance uniform and scattering from the counter stream of K
// (candidates.hpp), as in the exact scheme.
//
// Segments. A segment ends after a strain of 0.1, half a mean collision time or at the
// stop asked for, whichever is first; then every W is replaced by its V (a rebase: sig = 0,
// lam = 1), the mass-weighted mean velocity (zero but for rounding) is removed, and
//   - with the thermostat, the energy is set to its initial value exactly (rounding only);
//   - without it, the gas is kept in scaled velocities as the freely cooling gas is
//     (granular.hpp): the stored velocities are brought back to kT0, log_scale records the
//     factor, the engine's clock runs in mean collision times of the scaled gas and
//     real_time in those at kT0. The shear rate a is per unit of real time, so the strain
//     per unit of the clock is a exp(-a_m log_scale).
// Every call of the engine's advance ends with a rebase, so what an observer, a checkpoint
// or Python sees are the true (scaled) velocities. The stops therefore take part in the
// trajectory: a run stopped at other instants is another realisation of the same process
// (the command's stops are a function of its options, so resume continues bit for bit).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/detail/state.hpp"
#include "hypergas/dsmc/granular.hpp"
#include "hypergas/dsmc/time_unit.hpp"
#include "hypergas/error.hpp"

namespace hypergas::dsmc::detail {

/// Whether the run has a shear flow.
template <int D, class Model, Features F>
bool sheared(const State<D, Model, F>& s) {
  return s.cfg.shear_rate != 0.0;
}

/// Whether the stored velocities are scaled (log_scale, real_time): a freely cooling
/// granular gas, or a sheared gas without thermostat.
template <int D, class Model, Features F>
bool scaled_state(const State<D, Model, F>& s) {
  return cooling(s) || (sheared(s) && s.cfg.thermostat == Thermostat::none);
}

/// The map V = lam S(sig) W of a segment and the thermostat's sums (see the file comment).
struct ShearMap {
  double sig = 0.0;  // strain since the segment began
  double lam = 1.0;  // thermostat factor (1 without thermostat)
  double A = 0.0, B = 0.0, C = 0.0, E0 = 0.0;  // thermostat sums of the stored W

  /// lam at strain s from the sums (thermostat on).
  double lam_at(double s) const { return std::sqrt(E0 / (A - 2.0 * s * B + s * s * C)); }
  /// The largest lam over strains [s0, s1] (Q convex: its minimum is at B / C, clamped).
  double lam_max(double s0, double s1) const {
    const double sm = C > 0.0 ? std::clamp(B / C, s0, s1) : s1;
    return std::max({lam_at(s0), lam_at(s1), lam_at(sm)});
  }
  /// The spectral norm of S(s): (|s| + sqrt(s^2 + 4)) / 2.
  static double norm(double s) { return 0.5 * (std::abs(s) + std::sqrt(s * s + 4.0)); }
  /// The stored w becomes the true velocity lam S(s) w, and back.
  template <int D>
  static void to_true(double* w, double s, double lam) {
    w[0] -= s * w[1];
    for (int k = 0; k < D; ++k) w[k] *= lam;
  }
  template <int D>
  static void to_stored(double* w, double s, double lam) {
    for (int k = 0; k < D; ++k) w[k] /= lam;
    w[0] += s * w[1];
  }
  /// Adds (sign 1) or removes (-1) a pair's terms of the thermostat's sums A, B, C.
  template <int D>
  void account(const double* wi, const double* wj, double mi, double mj, double sign) {
    double ui = 0.0, uj = 0.0;
    for (int k = 0; k < D; ++k) ui += wi[k] * wi[k], uj += wj[k] * wj[k];
    A += sign * (mi * ui + mj * uj);
    B += sign * (mi * wi[0] * wi[1] + mj * wj[0] * wj[1]);
    C += sign * (mi * wi[1] * wi[1] + mj * wj[1] * wj[1]);
  }
};

/// Replaces every stored W by V = lam S(sig) W, removes the mean velocity and normalises
/// the energy (granular.hpp's renormalise; see the file comment), which sets the speed
/// bound. Leaves sig = 0, lam = 1 and the thermostat's sums of the new W.
template <int D, class Model, Features F>
void rebase(State<D, Model, F>& s, ShearMap& m) {
  constexpr int S = State<D, Model, F>::stride;
  double* v = s.p.velocity_data().data();
  const std::size_t n = s.p.size();
  for (std::size_t i = 0; i < n; ++i) ShearMap::to_true<D>(v + i * S, m.sig, m.lam);
  const bool thermostat = s.cfg.thermostat == Thermostat::isokinetic;
  renormalise(s, !thermostat);
  m = ShearMap{};
  if (thermostat) {
    for (std::size_t i = 0; i < n; ++i) {
      const double* w = v + i * S;
      const double mi = s.p.mass(i);
      double u = 0.0;
      for (int k = 0; k < D; ++k) u += w[k] * w[k];
      m.A += mi * u;
      m.B += mi * w[0] * w[1];
      m.C += mi * w[1] * w[1];
    }
    m.E0 = m.A;
  }
}

/// Advances a sheared gas to t_end (exact scheme; see the file comment). Ends with a rebase.
template <int D, class Model, Features F>
void advance_sheared(State<D, Model, F>& s, const std::function<void()>& poll, double t_end) {
  constexpr int S = State<D, Model, F>::stride;
  constexpr double max_strain = 0.1, max_span = 0.5;
  constexpr std::uint64_t ahead = 8;  // candidates between a prefetch and its use
  const bool thermostat = s.cfg.thermostat == Thermostat::isokinetic;
  const double am = s.model.exponent();
  ShearMap m;
  double* v = s.p.velocity_data().data();
  if (s.time < t_end) rebase(s, m);  // the sums of the thermostat (the state is already V)
  while (s.time < t_end) {
    const double rate = s.cfg.shear_rate * std::exp(-am * s.log_scale);  // strain per clock unit
    const double t0 = s.time;
    const double te = std::min({t_end, t0 + max_strain / rate, t0 + max_span});
    if (!(te > t0))
      throw InvalidInput("DSMC: the clock (t = " + std::to_string(t0) +
                         ") is too large to resolve the shear flow's strain");
    const double s_end = rate * (te - t0);
    // the bound G on |g| over the rest of the segment from strain `from` on
    const auto set_rate = [&](double from) {
      double G = s.bound.bound() * ShearMap::norm(s_end);
      if (thermostat) G *= m.lam_max(from, s_end);
      s.lambda = 0.5 * s.n * s.c * (!Model::needs_majorant ? 1.0 : am == 1.0 ? G : std::pow(G, am));
      return G;
    };
    double G = set_rate(0.0);
    double t = t0;
    for (;;) {
      t += s.rng.exponential() / s.lambda;
      if (!(t < te)) break;
      const std::uint64_t K = s.candidates++;
      std::uint32_t i, j;
      double u;
      s.draw(K, i, j, u);
      {
        // the pair of a candidate `ahead` further on is a function of its number alone:
        // fetch its two velocities now, so that a large gas waits on memory less often
        std::uint32_t pi, pj;
        s.draw_pair(K + ahead, pi, pj);
        __builtin_prefetch(v + std::size_t(pi) * S);
        __builtin_prefetch(v + std::size_t(pj) * S);
      }
      const double sig = rate * (t - t0);
      const double lam = thermostat ? m.lam_at(sig) : 1.0;
      double* wi = v + std::size_t(i) * S;
      double* wj = v + std::size_t(j) * S;
      if constexpr (Model::needs_majorant) {
        double g2 = 0.0;
        for (int k = 0; k < D; ++k) {
          double g = wi[k] - wj[k];
          if (k == 0) g -= sig * (wi[1] - wj[1]);
          g2 += g * g;
        }
        if (!s.model.accept(lam * lam * g2, u, G)) continue;
      }
      // to true velocities, collide, and back
      const double mi = thermostat ? s.p.mass(i) : 0.0, mj = thermostat ? s.p.mass(j) : 0.0;
      if (thermostat) m.account<D>(wi, wj, mi, mj, -1.0);
      ShearMap::to_true<D>(wi, sig, lam);
      ShearMap::to_true<D>(wj, sig, lam);
      collide_pair<Model>(s.p, i, j, s.impulse, s.draws.scattering(K), K, NoHook{});
      ++s.collisions;
      ShearMap::to_stored<D>(wi, sig, lam);
      ShearMap::to_stored<D>(wj, sig, lam);
      if (thermostat) m.account<D>(wi, wj, mi, mj, 1.0);
      if constexpr (Model::needs_majorant) {
        double ui = 0.0, uj = 0.0;
        for (int k = 0; k < D; ++k) ui += wi[k] * wi[k], uj += wj[k] * wj[k];
        const double u2 = std::max(ui, uj);
        const bool raised = s.bound.exceeded_by(u2);
        if (raised) s.bound.set(u2);
        // the new bound (or the thermostat's new sums) from this candidate on
        if (raised || thermostat) G = set_rate(sig);
      }
    }
    m.sig = s_end;
    if (thermostat) m.lam = m.lam_at(s_end);
    s.time = te;
    if (scaled_state(s)) s.real_time += (te - t0) * std::exp(-am * s.log_scale);
    rebase(s, m);
    if (poll) poll();
  }
}

}  // namespace hypergas::dsmc::detail
