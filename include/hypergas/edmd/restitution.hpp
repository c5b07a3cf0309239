// hypergas/edmd/restitution.hpp -- the inelastic (granular) binary collision of smooth hard
// spheres with a constant coefficient of normal restitution alpha, and the checks of the
// granular parameters of an EDMD run.
//
// With g = v2 - v1, the unit normal n from 2 to 1 and the weights a_k = w_k / (w1 + w2)
// (w_k = 1/m_k) of the elastic kernel (hypergas/collision.hpp), the normal relative
// velocity g.n becomes -alpha g.n:
//
//     v1' = v1 + (1 + alpha) a1 (g.n) n,     v2' = v2 - (1 + alpha) a2 (g.n) n.
//
// Momentum is conserved; the kinetic energy lost is (1 - alpha^2)/2 mu (g.n)^2 with
// mu = m1 m2 / (m1 + m2) the reduced mass. alpha = 1 is the elastic kernel itself
// (detail::collide_unchecked, called as is: elastic trajectories are unchanged bit for bit);
// alpha = 0 makes the pair leave with equal normal velocities.
//
// In D = 1 the normal is a sign and drops out: v1' = v1 + (1 + alpha) a1 (v2 - v1),
// v2' = v2 - (1 + alpha) a2 (v2 - v1). Equal masses no longer swap velocities when
// alpha < 1: the pair's relative velocity is reversed and scaled by alpha.
//
// Inelastic collapse (infinitely many collisions in finite time among a few particles, as
// soon as alpha is low enough or the gas dense enough) is avoided by the TC model of
// S. Luding & S. McNamara, "How to handle the inelastic collapse of a dissipative
// hard-sphere gas with the TC model", Granular Matter 1, 113 (1998): a collision is
// elastic when either particle had its previous collision less than t_c ago (tc_elastic).
// A particle's first collision after dissipation is switched on has no previous one.
// Without it (t_c = 0), or at very low alpha, groups of particles collapse: bursts of
// collisions at one instant, ended only by round-off. The engine also keeps every pair it
// collided inelastically receding by more than round-off (keep_receding).
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "hypergas/collision.hpp"
#include "hypergas/error.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::edmd {

/// Inelastic collision of particles 1 and 2 in place (see the file comment): inverse
/// masses w1, w2 (w1 + w2 > 0), unit normal n from 2 to 1, restitution alpha in [0, 1].
/// alpha == 1 calls the elastic kernel detail::collide_unchecked unchanged.
template <int D, class V1, class V2>
inline void collide_inelastic(V1&& v1, V2&& v2, double w1, double w2, const Vec<D>& n,
                              double alpha) {
  if (alpha == 1.0) {
    detail::collide_unchecked<D>(v1, v2, w1, w2, n);
    return;
  }
  const double wsum = w1 + w2;
  const double b1 = (1.0 + alpha) * (w1 / wsum);
  const double b2 = (1.0 + alpha) * (w2 / wsum);
  if constexpr (D == 1) {
    (void)n;
    const double g = v2[0] - v1[0];
    v1[0] += b1 * g;
    v2[0] -= b2 * g;
  } else {
    const double gn = (v2 - v1).dot(n);
    v1 += (b1 * gn) * n;
    v2 -= (b2 * gn) * n;
  }
}

/// Keeps a pair that has just collided receding along n by more than round-off: if
/// g.n = (v2 - v1).n (negative when receding, n from 2 to 1) is above
/// -64 eps (|v1| + |v2|), a normal impulse (momentum conserving, weights as in the kernel)
/// sets it to that value. An inelastic collision leaves g.n = -alpha (g.n before), which is
/// zero to round-off for alpha = 0 or a nearly grazing pair; with the wrong sign the event
/// prediction would see the touching pair approach and collide it again at the same
/// instant, without end when the velocity change rounds away. The energy this adds is of
/// order (eps |v|)^2 mu.
template <int D, class V1, class V2>
inline void keep_receding(V1&& v1, V2&& v2, double w1, double w2, const Vec<D>& n) {
  const double gn = (v2 - v1).dot(n);
  const double floor =
      64.0 * std::numeric_limits<double>::epsilon() * (v1.norm() + v2.norm());
  if (gn > -floor) {
    const double wsum = w1 + w2;
    const double d = gn + floor;
    v1 += (d * (w1 / wsum)) * n;
    v2 -= (d * (w2 / wsum)) * n;
  }
}

/// Kinetic energy a collision with restitution alpha takes from a pair of inverse masses
/// w1, w2 whose normal relative velocity is gn: (1 - alpha^2)/2 mu gn^2, mu = 1/(w1 + w2).
inline double inelastic_energy_loss(double w1, double w2, double gn, double alpha) {
  return 0.5 * (1.0 - alpha * alpha) * gn * gn / (w1 + w2);
}

/// Throws InvalidInput unless alpha is a coefficient of restitution: finite, in [0, 1].
inline void check_restitution(double alpha) {
  if (!(std::isfinite(alpha) && alpha >= 0.0 && alpha <= 1.0))
    throw InvalidInput("coefficient of restitution must be finite and in [0, 1], got " +
                       std::to_string(alpha));
}

/// Throws InvalidInput unless t_c (TC model) is finite and >= 0.
inline void check_tc_time(double tc) {
  if (!(std::isfinite(tc) && tc >= 0.0))
    throw InvalidInput("TC-model time tc_time must be finite and >= 0, got " +
                       std::to_string(tc));
}

}  // namespace hypergas::edmd
