// hypergas/edmd/pair_time.hpp -- the time to contact of two moving (and possibly growing)
// spheres, from a numerically stable root of the contact quadratic.
//
// Relative position r = x_j - x_i and velocity v = v_j - v_i at the current time; contact
// distance s (sum of radii) growing at rate a (0 except during Lubachevsky–Stillinger
// compression). Contact at time tau solves |r + v tau| = s + a tau:
//
//     A tau^2 + 2 B tau + C = 0,   A = v.v - a^2,  B = r.v - s a,  C = r.r - s^2.
//
// The earliest non-negative root is written as tau = C / (-B + sqrt(B^2 - A C)) (the
// "citardauq" form): for approaching pairs (B < 0) numerator and denominator are sums of
// terms of one sign, so there is no cancellation when the pair nearly touches (C -> 0) or
// nearly grazes (B^2 - A C -> 0), and no division by a vanishing A. For a = 0 this is the
// root t = (r^2 - sigma^2) / (-b + sqrt(b^2 - v^2 (r^2 - sigma^2))).
//
// A pair found overlapping by round-off (C <= 0) while approaching (B < 0) collides at
// once (tau = 0) instead of tunnelling through.
#pragma once

#include <cmath>
#include <limits>

namespace hypergas::edmd {

/// "Never" as an event time.
inline constexpr double never = std::numeric_limits<double>::infinity();

/// Time (same unit as r/v) until |r + v tau| = s + a tau, or `never`. Arguments: rv = r.v,
/// vv = v.v, rr = r.r, s = contact distance now (length), a = its growth rate (length/time).
inline double contact_time(double rv, double vv, double rr, double s, double a = 0.0) {
  const double B = rv - s * a;
  const double C = rr - s * s;
  const double A = vv - a * a;
  if (C <= 0.0) return B < 0.0 ? 0.0 : never;  // touching/overlapping: collide iff approaching
  if (B >= 0.0 && A >= 0.0) return never;      // separating faster than the spheres grow
  const double disc = B * B - A * C;
  if (disc < 0.0) return never;  // the paths miss (only possible for A > 0)
  const double den = std::sqrt(disc) - B;
  if (!(den > 0.0)) return never;
  return C / den;
}

}  // namespace hypergas::edmd
