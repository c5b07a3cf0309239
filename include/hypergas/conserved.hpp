// hypergas/conserved.hpp -- the conserved quantities of a gas, for both engines.
//
// Sums in long double, so that the drift of a run of 1e7 collisions is measured well below
// the 1e-12 the tests and summary.json report; particles of infinite mass (inverse mass 0)
// carry no energy and are left out.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "hypergas/particles.hpp"

namespace hypergas {

/// Total momentum sum m v, kinetic energy sum m |v|^2 / 2 and the momentum scale sum m |v|
/// (the yardstick of momentum drift) of a particle set; mass of species 0 = 1.
template <int D>
struct Conserved {
  std::array<long double, D> momentum{};
  long double energy = 0.0L;
  long double momentum_scale = 0.0L;
};

/// Adds one particle of inverse mass w and velocity v[0 .. dim) to `c` (dim <= D: the
/// sums of a runtime dimension, as a snapshot's, in a Conserved of the largest D); a
/// particle of infinite mass (w = 0) adds nothing.
template <int D, class V>
void add_particle(Conserved<D>& c, const V& v, int dim, double w) {
  if (!(w > 0.0)) return;
  const long double m = 1.0L / w;
  long double v2 = 0.0L;
  for (int k = 0; k < dim; ++k) {
    const long double vk = v[k];
    v2 += vk * vk;
    c.momentum[k] += m * vk;
  }
  c.energy += 0.5L * m * v2;
  c.momentum_scale += m * std::sqrt(v2);
}

/// Sums of momentum and energy over `p` (O(N)).
template <int D, Features F>
Conserved<D> conserved(const Particles<D, F>& p) {
  Conserved<D> c;
  for (std::size_t i = 0; i < p.size(); ++i) add_particle(c, p.velocity(i), D, p.inv_mass(i));
  return c;
}

/// Relative energy drift |E1 - E0| / E0 (dimensionless; 0 if E0 = 0).
template <int D>
double energy_rel_drift(const Conserved<D>& a, const Conserved<D>& b) {
  return a.energy > 0.0L ? static_cast<double>(std::fabs(b.energy - a.energy) / a.energy) : 0.0;
}

/// Momentum drift |P1 - P0| / (sum m |v| at the start) (dimensionless; 0 if that is 0).
template <int D>
double momentum_drift(const Conserved<D>& a, const Conserved<D>& b) {
  long double d2 = 0.0L;
  for (int k = 0; k < D; ++k) {
    const long double dp = b.momentum[k] - a.momentum[k];
    d2 += dp * dp;
  }
  return a.momentum_scale > 0.0L ? static_cast<double>(std::sqrt(d2) / a.momentum_scale) : 0.0;
}

}  // namespace hypergas
