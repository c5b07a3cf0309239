// hypergas/dsmc/conserved.hpp -- the conserved quantities of a velocity-space gas.
#pragma once

#include <cmath>
#include <cstddef>

#include "hypergas/particles.hpp"

namespace hypergas::dsmc {

/// Total momentum, kinetic energy and a momentum scale of a particle set.
template <int D>
struct Conserved {
  Vec<D> momentum = Vec<D>::Zero();  ///< sum m v (mass of species 0 = 1)
  double energy = 0.0;               ///< sum m |v|^2 / 2
  double momentum_scale = 0.0;       ///< sum m |v|: the yardstick for momentum drift
};

/// Sums of momentum and energy over `p` (O(N)).
template <int D, Features F>
Conserved<D> conserved(const Particles<D, F>& p) {
  Conserved<D> c;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double m = 1.0 / p.inv_mass(i);
    const auto v = p.velocity(i);
    c.momentum += m * v;
    const double v2 = v.squaredNorm();
    c.energy += 0.5 * m * v2;
    c.momentum_scale += m * std::sqrt(v2);
  }
  return c;
}

}  // namespace hypergas::dsmc
