// hypergas/dsmc/update.hpp -- the one place where a DSMC collision changes velocities.
//
// The collision models (models.hpp) return the new relative velocity g' of g = v_i - v_j;
// the velocities are then updated by the shared seed kernel in its relative-velocity form,
// hypergas::detail::exchange_relative (collision.hpp), with the masses of the scene, or for
// restitution below 1 by the inelastic rule in that form, hypergas::exchange_inelastic
// (restitution.hpp).
#pragma once

#include <cstdint>
#include <utility>

#include "hypergas/collision.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/restitution.hpp"

namespace hypergas::dsmc {

/// Applies the change dg = g' - g of the relative velocity of particles i and j (views vi,
/// vj into p's velocity array), scaled by `impulse` = restitution_impulse(alpha) =
/// (1 + alpha)/2 for a coefficient of restitution alpha (restitution.hpp, dsmc/granular.hpp;
/// 1: elastic, dg as it is). Single-mass scenes
/// compile the weights to 1/2; in D = 1 an elastic collision of equal masses has g' = +-g
/// and is done as an exact keep-or-swap.
template <int D, Features F, class VI, class VJ>
[[gnu::always_inline]] inline void apply_deflection(const Particles<D, F>& p, std::uint32_t i,
                                                std::uint32_t j, VI&& vi,
                                                VJ&& vj, const Vec<D>& dg, double impulse) {
  constexpr bool equal_masses = !F.species;
  if (impulse != 1.0) [[unlikely]] {
    hypergas::exchange_inelastic<D, equal_masses>(vi, vj, p.inv_mass(i), p.inv_mass(j), dg,
                                                  impulse);
    return;
  }
  if constexpr (equal_masses && D == 1) {
    if (dg[0] != 0.0) std::swap(vi[0], vj[0]);
  } else {
    hypergas::detail::exchange_relative<D, equal_masses>(vi, vj, p.inv_mass(i), p.inv_mass(j), dg);
  }
}

}  // namespace hypergas::dsmc
