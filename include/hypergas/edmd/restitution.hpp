// hypergas/edmd/restitution.hpp -- what the EDMD engine adds to the inelastic collision
// rule of hypergas/restitution.hpp (collide_inelastic, its normal form, and the one check
// of alpha, check_restitution): the TC model, keeping collided pairs receding, and the check
// of the TC time.
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

#include "hypergas/error.hpp"
#include "hypergas/restitution.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::edmd {

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

/// Throws InvalidInput unless t_c (TC model) is finite and >= 0.
inline void check_tc_time(double tc) {
  if (!(std::isfinite(tc) && tc >= 0.0))
    throw InvalidInput("TC-model time tc_time must be finite and >= 0, got " +
                       std::to_string(tc));
}

}  // namespace hypergas::edmd
