// hypergas/edmd/pair_time.hpp -- the time to contact of two moving (and possibly growing)
// spheres, from a numerically stable root of the contact quadratic.
//
// Relative position r = x_j - x_i and velocity v = v_j - v_i at the current time; contact
// distance s (the diameter) growing at rate a (0 except during Lubachevsky–Stillinger
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
#include <cstddef>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

/// contact_time for n pairs at once, without a branch on the data: the same operations in
/// the same order (so the same results, bit for bit), with the case analysis as selects.
/// A scan's candidates approach or recede at random, so contact_time's early returns
/// mispredict about every other pair; here every pair pays for the square root and the
/// division instead. Every pair has contact distance sc growing at `rate`; arrays of
/// length n.
inline void contact_times(std::size_t n, const double* rv, const double* vv, const double* rr,
                          double sc, double rate, double* t) {
  std::size_t c = 0;
#if defined(__SSE2__)
  // Two pairs per step (GCC 12 turns the scalar selects below back into branches).
  const __m128d zero = _mm_setzero_pd(), inf = _mm_set1_pd(never);
  const __m128d s = _mm_set1_pd(sc), a = _mm_set1_pd(rate);
  for (; c + 2 <= n; c += 2) {
    const __m128d B = _mm_sub_pd(_mm_loadu_pd(rv + c), _mm_mul_pd(s, a));
    const __m128d C = _mm_sub_pd(_mm_loadu_pd(rr + c), _mm_mul_pd(s, s));
    const __m128d A = _mm_sub_pd(_mm_loadu_pd(vv + c), _mm_mul_pd(a, a));
    const __m128d disc = _mm_sub_pd(_mm_mul_pd(B, B), _mm_mul_pd(A, C));
    const __m128d den = _mm_sub_pd(_mm_sqrt_pd(_mm_max_pd(disc, zero)), B);
    const __m128d far = _mm_div_pd(C, den);
    const __m128d recede = _mm_and_pd(_mm_cmpge_pd(B, zero), _mm_cmpge_pd(A, zero));
    const __m128d hit =
        _mm_andnot_pd(recede, _mm_and_pd(_mm_cmpge_pd(disc, zero), _mm_cmpgt_pd(den, zero)));
    const __m128d apart = _mm_or_pd(_mm_and_pd(hit, far), _mm_andnot_pd(hit, inf));
    const __m128d touch = _mm_andnot_pd(_mm_cmplt_pd(B, zero), inf);
    const __m128d close = _mm_cmple_pd(C, zero);
    _mm_storeu_pd(t + c, _mm_or_pd(_mm_and_pd(close, touch), _mm_andnot_pd(close, apart)));
  }
#endif
  for (; c < n; ++c) {
    const double s = sc, a = rate;
    const double B = rv[c] - s * a;
    const double C = rr[c] - s * s;
    const double A = vv[c] - a * a;
    const double disc = B * B - A * C;
    const double den = std::sqrt(disc > 0.0 ? disc : 0.0) - B;
    const double far = C / den;
    const bool hit = !(B >= 0.0 && A >= 0.0) && disc >= 0.0 && den > 0.0;
    const double apart = hit ? far : never;
    const double touch = B < 0.0 ? 0.0 : never;
    t[c] = C <= 0.0 ? touch : apart;
  }
}

}  // namespace hypergas::edmd
