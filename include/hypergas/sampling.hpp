// hypergas/sampling.hpp -- random directions and velocities in D dimensions.
#pragma once

#include <cmath>

#include "hypergas/rng.hpp"
#include "hypergas/vec.hpp"

namespace hypergas {

/// D independent standard normal deviates.
template <int D>
Vec<D> normal_vector(Rng& rng) {
  Vec<D> w;
  for (int k = 0; k < D; ++k) w[k] = rng.normal();
  return w;
}

/// Uniformly distributed unit vector on the sphere S^(D-1) (normalised Gaussian vector;
/// in D = 1 a random sign).
template <int D>
Vec<D> unit_vector(Rng& rng) {
  if constexpr (D == 1) {
    return Vec<D>::Constant((rng() >> 63) ? 1.0 : -1.0);
  } else {
    for (;;) {
      const Vec<D> w = normal_vector<D>(rng);
      const double nn = w.squaredNorm();
      if (nn > 0.0) return w / std::sqrt(nn);  // nn == 0 has probability ~0; redraw
    }
  }
}

/// Maxwell–Boltzmann velocity: each component normal with variance kT/m (any unit).
template <int D>
Vec<D> maxwell_velocity(Rng& rng, double kT_over_m) {
  return std::sqrt(kT_over_m) * normal_vector<D>(rng);
}

/// Hard-sphere collision normal for relative velocity g = v2 - v1: a unit vector n with
/// g . n >= 0 and density proportional to (g_hat . n) on that hemisphere, which is the
/// distribution of the line of centres at contact for uniformly distributed impact
/// parameters. Sampled in O(D) without rejection:
///   t = g_hat . n has density  f(t) ~ t (1 - t^2)^((D-3)/2)  on [0, 1];
///   with s = 1 - t^2 this is s ~ Beta((D-1)/2, 1), i.e. s = U^(2/(D-1)), U uniform;
///   n = t g_hat + sqrt(s) e, e uniform on the unit sphere orthogonal to g_hat.
/// In D = 1, n = sign(g). For g = 0 (no collision happens) any unit vector is returned.
template <int D>
Vec<D> hard_sphere_normal(Rng& rng, const Vec<D>& g) {
  const double gg = g.squaredNorm();
  if (!(gg > 0.0)) return unit_vector<D>(rng);
  // Scale first so that |g| is computed without overflow or underflow for any finite g.
  const double gmax = g.cwiseAbs().maxCoeff();
  const Vec<D> gs = g / gmax;
  const Vec<D> gh = gs / gs.norm();
  if constexpr (D == 1) {
    return gh;
  } else {
    const double u = rng.uniform_pos();
    const double sin_t = (D == 3) ? std::sqrt(u) : std::pow(u, 1.0 / (D - 1));
    const double cos_t = std::sqrt(std::max(0.0, 1.0 - sin_t * sin_t));
    for (;;) {
      Vec<D> e = normal_vector<D>(rng);
      e -= e.dot(gh) * gh;
      const double ee = e.squaredNorm();
      if (ee > 1e-300) {
        Vec<D> n = cos_t * gh + (sin_t / std::sqrt(ee)) * e;
        return n / n.norm();  // re-normalise to one rounding
      }
    }
  }
}

}  // namespace hypergas
