// hypergas/dsmc/majorant.hpp -- a provable upper bound on every pair's relative speed.
//
// For any two particles |v_i - v_j| <= |v_i| + |v_j| <= 2 vmax, vmax = max_i |v_i|, in any
// frame. The bound G kept here is 2 sqrt(limit2) with limit2 >= vmax^2 at every moment: the
// engine compares the squared speeds of the two particles after each accepted collision
// with limit2 and raises the bound (a stop event) before the next candidate is drawn, so
// no pair is ever under-sampled. Raising adds a small margin so that a slowly growing
// tail does not stop the engine at every record; `rescan` tightens the bound to the exact
// maximum again (the maximum can also fall).
#pragma once

#include <algorithm>
#include <cmath>

#include "hypergas/particles.hpp"

namespace hypergas::dsmc {

/// Bound G on all relative speeds (velocity units of the particles).
class SpeedBound {
 public:
  /// Relative margin added when the bound is set: G = 2 vmax (1 + margin).
  static constexpr double margin = 0.02;

  /// Sets the bound from the exact maximum speed of `p` (O(N) sequential scan).
  template <int D, Features F>
  void rescan(const Particles<D, F>& p) {
    rescan(p, 0, p.size());
  }
  /// The same over particles [b, e) only (a lane of the lanes scheme).
  template <int D, Features F>
  void rescan(const Particles<D, F>& p, std::size_t b, std::size_t e) {
    double m = 0.0;
    const double* v = p.velocity_data().data();
    constexpr int S = Particles<D, F>::stride;
    for (std::size_t i = b; i < e; ++i) {
      double s = 0.0;
      for (int k = 0; k < D; ++k) s += v[i * S + k] * v[i * S + k];
      m = std::max(m, s);
    }
    set(m);
  }
  /// Sets the bound for a maximum squared speed v2 (adds the margin).
  void set(double v2) {
    limit2_ = v2 * (1.0 + margin) * (1.0 + margin);
    bound_ = 2.0 * std::sqrt(limit2_);
  }
  /// True if a particle with squared speed v2 is not covered by the bound.
  bool exceeded_by(double v2) const { return v2 > limit2_; }
  /// G: upper bound of |v_i - v_j| over all pairs.
  double bound() const { return bound_; }
  /// G^a, the factor of the candidate rate for the rate exponent a.
  double bound_power(double a) const { return a == 1.0 ? bound_ : std::pow(bound_, a); }

 private:
  double limit2_ = 0.0;
  double bound_ = 0.0;
};

}  // namespace hypergas::dsmc
