// hypergas/collision.hpp -- the elastic binary collision kernel of the seed document.
//
// Two particles with velocities v1, v2 and masses m1, m2 collide along the unit normal n
// (n points from particle 2 to particle 1: n = (P1 - P2)/|P1 - P2|). With g = v2 - v1 the
// seed gives the impulse form
//
//     J   = 2 (g . n) / (1/m1 + 1/m2)            (momentum given to particle 1 along n)
//     v1' = v1 + J (1/m1) n,     v2' = v2 - J (1/m2) n.
//
// We never form J itself (it overflows for m ~ 1e12 and v ~ 1e150). With inverse masses
// w1 = 1/m1, w2 = 1/m2 and the exactly computed weights a1 = w1/(w1+w2), a2 = w2/(w1+w2)
// (a1 + a2 = 1 to one rounding, both in [0, 1]):
//
//     v1' = v1 + 2 a1 (g . n) n,     v2' = v2 - 2 a2 (g . n) n.
//
// An infinite mass is w = 0: its weight is 0, it does not move, and the other particle's
// normal velocity relative to it is reflected (a moving wall). Every intermediate is of the
// size of the velocities, so magnitudes from 1e-150 to 1e150 and mass ratios 1e-12..1e12
// neither overflow nor underflow.
//
// In D = 1 the normal is only a sign and the result does not depend on it; there we use the
// seed's first form v1' = ((m1 - m2) v1 + 2 m2 v2)/(m1 + m2), written with weights, whose
// coefficients are exactly 0 and 1 for equal masses: equal masses swap velocities exactly.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "hypergas/error.hpp"
#include "hypergas/vec.hpp"

namespace hypergas {

/// Largest accepted | |n|^2 - 1 | for a normal passed to the checked `collide`.
inline constexpr double normal_tolerance = 1e-12;

namespace detail {

/// The kernel without checks, for hot loops whose normal is unit by construction.
/// `v1`, `v2` are any Eigen vector expressions that can be assigned (Map, Vec, Block).
/// Precondition: w1, w2 >= 0, w1 + w2 > 0, |n| = 1 to round-off.
template <int D, class V1, class V2>
inline void collide_unchecked(V1&& v1, V2&& v2, double w1, double w2, const Vec<D>& n) {
  const double wsum = w1 + w2;
  const double a1 = w1 / wsum;
  const double a2 = w2 / wsum;
  if constexpr (D == 1) {
    const double u1 = v1[0];
    const double u2 = v2[0];
    v1[0] = (a2 - a1) * u1 + 2.0 * a1 * u2;
    v2[0] = (a1 - a2) * u2 + 2.0 * a2 * u1;
  } else {
    const double gn = (v2 - v1).dot(n);
    v1 += (2.0 * a1 * gn) * n;
    v2 -= (2.0 * a2 * gn) * n;
  }
}

/// The same kernel written for a given change of relative velocity, as the velocity-space
/// engine uses it: its collision models produce the new relative velocity g' of
/// g = v1 - v2 directly (for hard spheres g' = g - 2 (g.n) n, the seed's reflection; for
/// isotropic models any g' with |g'| = |g|, which is the reflection at the normal
/// n = (g - g')/|g - g'|). With dg = g' - g the seed's update is
///     v1' = v1 + a1 dg,   v2' = v2 - a2 dg,   a_k = w_k / (w1 + w2),
/// which conserves momentum exactly in exact arithmetic and energy because |g'| = |g|.
/// `EqualMass` compiles the weights to 1/2 for single-mass scenes.
template <int D, bool EqualMass = false, class V1, class V2>
inline void exchange_relative(V1&& v1, V2&& v2, double w1, double w2, const Vec<D>& dg) {
  if constexpr (EqualMass) {
    (void)w1, (void)w2;
    v1 += 0.5 * dg;
    v2 -= 0.5 * dg;
  } else {
    const double wsum = w1 + w2;
    v1 += (w1 / wsum) * dg;
    v2 -= (w2 / wsum) * dg;
  }
}

}  // namespace detail

/// Throws InvalidInput unless n is finite and |n|^2 is within `normal_tolerance` of 1.
template <int D>
inline void check_normal(const Vec<D>& n) {
  const double nn = n.squaredNorm();
  if (!n.allFinite() || !std::isfinite(nn)) throw InvalidInput("collision normal is not finite");
  if (nn == 0.0) throw InvalidInput("collision normal is zero (coincident centres?)");
  if (std::abs(nn - 1.0) > normal_tolerance)
    throw InvalidInput("collision normal is not unit length: |n|^2 = " + std::to_string(nn));
}

/// Throws InvalidInput unless both inverse masses are finite and >= 0 and not both 0.
inline void check_inverse_masses(double w1, double w2) {
  if (!(std::isfinite(w1) && std::isfinite(w2)) || w1 < 0.0 || w2 < 0.0)
    throw InvalidInput("inverse masses must be finite and >= 0 (0 is an infinite mass)");
  if (w1 + w2 == 0.0) throw InvalidInput("two infinite masses cannot collide");
}

/// Elastic collision of particles 1 and 2, in place. `w1`, `w2` are inverse masses
/// (1/mass; 0 for an infinite mass), `n` the unit normal from 2 to 1. Velocities in any
/// unit; the result is in the same unit. Throws InvalidInput for a zero, non-finite or
/// non-unit normal or for invalid masses; never produces a NaN from finite input.
template <int D, class V1, class V2>
inline void collide(V1&& v1, V2&& v2, double w1, double w2, const Vec<D>& n) {
  check_normal<D>(n);
  check_inverse_masses(w1, w2);
  detail::collide_unchecked<D>(v1, v2, w1, w2, n);
}

/// Convenience overload for plain vectors: returns the post-collision pair.
template <int D>
inline std::pair<Vec<D>, Vec<D>> collided(Vec<D> v1, Vec<D> v2, double w1, double w2,
                                          const Vec<D>& n) {
  collide<D>(v1, v2, w1, w2, n);
  return {v1, v2};
}

}  // namespace hypergas
