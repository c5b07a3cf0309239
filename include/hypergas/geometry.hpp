// hypergas/geometry.hpp -- unit-ball volume and sphere surface in D dimensions.
#pragma once

#include <cmath>
#include <numbers>

namespace hypergas {

/// Volume of the unit ball in D dimensions: pi^(D/2) / Gamma(D/2 + 1).
inline double unit_ball_volume(int d) {
  return std::pow(std::numbers::pi, 0.5 * d) / std::tgamma(0.5 * d + 1.0);
}

/// Surface area of the unit sphere S^(D-1): D times the unit-ball volume.
inline double unit_sphere_area(int d) {
  return d * unit_ball_volume(d);
}

/// Volume of a ball of diameter sigma in D dimensions.
inline double ball_volume(int d, double sigma) {
  return unit_ball_volume(d) * std::pow(0.5 * sigma, d);
}

}  // namespace hypergas
