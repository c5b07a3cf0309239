// hypergas/dsmc/scattering.hpp -- post-collision relative velocities, fast paths per D.
//
// An elastic binary collision keeps the centre-of-mass velocity and the relative speed |g|
// and turns the relative velocity g = v1 - v2 into g'. The collision models differ only in
// the law of the direction of g':
//   isotropic  g' = |g| sigma, sigma uniform on S^(D-1) (Maxwell molecules, VHS);
//   hard       g' = g - 2 (g.n) n, with the line of centres n distributed with density
//   spheres    proportional to (g_hat . n) on the hemisphere g_hat . n > 0 (specular
//              reflection at uniformly distributed impact parameters).
// Hard-sphere normals are drawn with Malley's projection, valid in every D: a point p
// uniform in the unit (D-1)-ball of the plane orthogonal to g_hat, lifted to the sphere,
// n = p + sqrt(1 - |p|^2) g_hat, has density proportional to g_hat . n (the Jacobian of the
// projection). Writing p = sqrt(s) omega (omega uniform on S^(D-2), sqrt(s) the largest of
// D - 1 uniforms) in a frame
// whose last axis is e_L, the frame is carried onto g_hat by one Householder reflection.
// In D = 3 hard-sphere scattering is isotropic in the centre-of-mass frame (cos chi =
// 2 s - 1 with s uniform), so the cheaper isotropic sampler is used there.
#pragma once

#include <algorithm>
#include <cmath>

#include "hypergas/rng.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::dsmc {

namespace detail {
/// A point (x, y) uniform in the open unit disk, by rejection from the square (acceptance
/// pi/4); returns s = x^2 + y^2. With NonZero the centre is rejected too, for callers that
/// divide by s (s is 0 or at least 2^-104 for 53-bit uniforms).
template <bool NonZero, class G>
inline double disk_point(G& rng, double& x, double& y) {
  for (;;) {
    x = 2.0 * rng.uniform() - 1.0;
    y = 2.0 * rng.uniform() - 1.0;
    const double s = x * x + y * y;
    if (s < 1.0 && (!NonZero || s != 0.0)) return s;
  }
}
/// Maximum of k uniforms on [0, 1): a variable with CDF x^k (k = D - 1 gives the radius of
/// a point uniform in the (D-1)-ball).
template <int K, class G>
inline double max_of_uniforms(G& rng) {
  double m = rng.uniform_pos();
  for (int k = 1; k < K; ++k) m = std::max(m, rng.uniform_pos());
  return m;
}
}  // namespace detail

/// Uniform unit vector on S^(D-1) without logarithms: Marsaglia's disk methods (1972,
/// "Choosing a point from the surface of a sphere", Ann. Math. Stat. 43) for D <= 4, and
/// for D = 5, 6 constructions on them without a rejection in the ball (see each branch).
template <int D, class G>
inline Vec<D> isotropic_direction(G& rng) {
  if constexpr (D == 1) {
    return Vec<D>::Constant((rng() >> 63) ? 1.0 : -1.0);
  } else if constexpr (D == 2) {
    // (x, y) uniform in the unit disk; its doubled angle is uniform: (x^2-y^2, 2xy)/(x^2+y^2).
    double x, y;
    const double s = detail::disk_point<true>(rng, x, y);
    return Vec<D>((x * x - y * y) / s, 2.0 * x * y / s);
  } else if constexpr (D == 3) {
    double x, y;
    const double s = detail::disk_point<false>(rng, x, y);
    const double f = 2.0 * std::sqrt(1.0 - s);
    return Vec<D>(x * f, y * f, 1.0 - 2.0 * s);
  } else if constexpr (D == 4) {
    double x1, y1, x2, y2;
    const double s1 = detail::disk_point<false>(rng, x1, y1);
    const double s2 = detail::disk_point<true>(rng, x2, y2);
    const double f = std::sqrt((1.0 - s1) / s2);
    Vec<D> v;
    v << x1, y1, x2 * f, y2 * f;
    return v;
  } else if constexpr (D == 5) {
    // One coordinate of sigma uniform on S^4 has density proportional to 1 - z^2 on
    // [-1, 1], the law of the median of three uniforms on [-1, 1] (density 6 x (1 - x) on
    // [0, 1], mapped); given z the other four are sqrt(1 - z^2) times a uniform point of S^3
    // (the D = 4 sampler). No rejection beyond the two disks of D = 4.
    const double a = 2.0 * rng.uniform() - 1.0, b = 2.0 * rng.uniform() - 1.0,
                 c = 2.0 * rng.uniform() - 1.0;
    const double z = std::max(std::min(a, b), std::min(std::max(a, b), c));
    const Vec<4> w = isotropic_direction<4>(rng);
    const double f = std::sqrt(1.0 - z * z);
    Vec<D> v;
    v << w[0] * f, w[1] * f, w[2] * f, w[3] * f, z;
    return v;
  } else if constexpr (D == 6) {
    // sigma uniform on S^5 as three planar pairs: their squared lengths are uniform on the
    // simplex (Dirichlet(1, 1, 1): the spacings of two sorted uniforms), their angles
    // uniform and independent (a point in the unit disk, normalised).
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const double lo = std::min(u1, u2), hi = std::max(u1, u2);
    const double r2[3] = {lo, hi - lo, 1.0 - hi};
    Vec<D> v;
    for (int k = 0; k < 3; ++k) {
      double x, y;
      const double s = detail::disk_point<true>(rng, x, y);
      const double f = std::sqrt(r2[k] / s);
      v[2 * k] = x * f;
      v[2 * k + 1] = y * f;
    }
    return v;
  } else {
    static_assert(D >= 1 && D <= 6, "directions are sampled for D = 1..6");
  }
}


/// Isotropic scattering: the new relative velocity |g| sigma, sigma uniform (any unit).
template <int D, class G>
inline Vec<D> isotropic_deflection(double gnorm, G& rng) {
  return gnorm * isotropic_direction<D>(rng);
}

/// Hard-sphere scattering: the new relative velocity g - 2 (g.n) n for the hard-sphere
/// normal distribution around g (see the file comment). Precondition gnorm = |g| > 0.
template <int D, class G>
inline Vec<D> hard_sphere_deflection(const Vec<D>& g, double gnorm, G& rng) {
  if constexpr (D == 1) {
    (void)gnorm;
    (void)rng;
    return -g;
  } else if constexpr (D == 3) {
    return isotropic_deflection<D>(gnorm, rng);
  } else {
    // s = 1 - t^2 ~ Beta((D-1)/2, 1) with t = g_hat . n: sqrt(s) = |p| has CDF x^(D-1),
    // the law of the largest of D - 1 uniforms.
    const double r = detail::max_of_uniforms<D - 1>(rng);
    const double s = r * r;
    const double t = std::sqrt(1.0 - s);
    // y = e_L - 2 t m with m = (sqrt(s) omega, t): the deflected direction in the frame.
    Vec<D> y;
    const Vec<D - 1> omega = isotropic_direction<D - 1>(rng);
    const double c = -2.0 * t * std::sqrt(s);
    for (int k = 0; k < D - 1; ++k) y[k] = c * omega[k];
    y[D - 1] = 1.0 - 2.0 * t * t;
    // Householder reflection H = I - 2 u u^T/(u.u), u = e_L - sp g_hat, maps e_L to sp g_hat;
    // the sign sp = -+1 is chosen so that u.u = 2 - 2 sp g_hat_L >= 2 (no cancellation).
    // Q = sp H is orthogonal with Q e_L = g_hat, so g' = |g| Q y.
    const Vec<D> gh = g / gnorm;
    const double sp = gh[D - 1] >= 0.0 ? -1.0 : 1.0;
    Vec<D> uh = -sp * gh;
    uh[D - 1] += 1.0;
    const Vec<D> hy = y - (2.0 * uh.dot(y) / uh.squaredNorm()) * uh;
    return (sp * gnorm) * hy;
  }
}

}  // namespace hypergas::dsmc
