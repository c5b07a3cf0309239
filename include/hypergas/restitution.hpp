// hypergas/restitution.hpp -- the inelastic (granular) binary collision of smooth hard
// spheres with a constant coefficient of normal restitution alpha: the one rule both
// engines apply, and the one check of alpha.
//
// A collision with restitution alpha gives the pair (1 + alpha)/2 of the elastic impulse
// along its normal: the normal relative velocity g.n becomes -alpha g.n, momentum is
// conserved and the kinetic energy lost is (1 - alpha^2)/2 mu (g.n)^2 with
// mu = m1 m2 / (m1 + m2) the reduced mass. alpha = 1 is the elastic kernel of
// collision.hpp itself (both engines call it unchanged then: elastic trajectories are
// bit for bit those of the seed); alpha = 0 makes the pair leave with equal normal
// velocities.
//
// The rule comes in the two forms of the elastic kernel, one per engine:
//   normal form (EDMD, collide_inelastic): with g = v2 - v1, the unit normal n from 2 to 1
//     and the weights a_k = w_k / (w1 + w2) (w_k = 1/m_k),
//         v1' = v1 + (1 + alpha) a1 (g.n) n,     v2' = v2 - (1 + alpha) a2 (g.n) n;
//     in D = 1 the normal is a sign and drops out: v1' = v1 + (1 + alpha) a1 (v2 - v1),
//     v2' = v2 - (1 + alpha) a2 (v2 - v1) (equal masses no longer swap velocities);
//   relative-velocity form (DSMC, exchange_inelastic): the collision model gives the
//     elastic change dg = g' - g of g = v1 - v2 (for hard spheres -2 (g.n) n), and
//         v1' = v1 + a1 (impulse dg),     v2' = v2 - a2 (impulse dg),
//     impulse = restitution_impulse(alpha) = (1 + alpha)/2.
// Each form keeps the floating-point operations its engine has always done, so that
// trajectories do not change.
#pragma once

#include <cmath>
#include <string>

#include "hypergas/collision.hpp"
#include "hypergas/error.hpp"
#include "hypergas/vec.hpp"

namespace hypergas {

/// Throws InvalidInput unless alpha is a coefficient of restitution: in [0, 1] (so finite,
/// not NaN). `who` starts the message ("DSMC: ", or empty).
inline void check_restitution(double alpha, const std::string& who = "") {
  if (!(alpha >= 0.0 && alpha <= 1.0))
    throw InvalidInput(who + "the coefficient of restitution must be in [0, 1], got " +
                       std::to_string(alpha));
}

/// The factor (1 + alpha)/2 of the elastic impulse that a collision with restitution alpha
/// gives (1: elastic).
inline double restitution_impulse(double alpha) { return 0.5 * (1.0 + alpha); }

/// Relative-velocity form (file comment): the elastic change dg of g = v1 - v2, scaled by
/// `impulse` = restitution_impulse(alpha), applied with inverse masses w1, w2 by the seed
/// kernel's detail::exchange_relative (`EqualMass`: weights 1/2).
template <int D, bool EqualMass = false, class V1, class V2>
inline void exchange_inelastic(V1&& v1, V2&& v2, double w1, double w2, const Vec<D>& dg,
                               double impulse) {
  detail::exchange_relative<D, EqualMass>(v1, v2, w1, w2, (impulse * dg).eval());
}

/// Normal form (file comment): particles 1 and 2 in place, inverse masses w1, w2
/// (w1 + w2 > 0), unit normal n from 2 to 1, restitution alpha in [0, 1]. alpha == 1 calls
/// the elastic kernel detail::collide_unchecked unchanged.
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

/// Kinetic energy a collision with restitution alpha takes from a pair of inverse masses
/// w1, w2 whose normal relative velocity is gn: (1 - alpha^2)/2 mu gn^2, mu = 1/(w1 + w2).
inline double inelastic_energy_loss(double w1, double w2, double gn, double alpha) {
  return 0.5 * (1.0 - alpha * alpha) * gn * gn / (w1 + w2);
}

}  // namespace hypergas
