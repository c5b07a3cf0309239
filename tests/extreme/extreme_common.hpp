// Shared helpers of the extreme-case tests: finiteness, conservation, replica statistics.
#pragma once

#include <cmath>
#include <cstddef>
#include <numeric>
#include <thread>
#include <utility>
#include <vector>

#include "hypergas/conserved.hpp"
#include "hypergas/particles.hpp"
#include "support/statistics.hpp"

namespace extreme {

/// True if every velocity component of `p` is finite (no NaN, no infinity).
template <int D, hypergas::Features F>
bool all_finite(const hypergas::Particles<D, F>& p) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!p.velocity(i).allFinite()) return false;
  return true;
}

/// Kinetic temperature sum m |v|^2 / (D n_s) of the n_s particles of species s.
template <int D, hypergas::Features F>
double species_temperature(const hypergas::Particles<D, F>& p, int s) {
  double e2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.species(i) == s) {
      e2 += p.velocity(i).squaredNorm() / p.inv_mass(i);
      ++n;
    }
  return e2 / (D * static_cast<double>(n));
}

/// Relative energy change |E1 - E0| / E0 and momentum change |P1 - P0| / (sum m |v|) of two
/// states of the same particles.
template <int D>
std::pair<double, double> drifts(const hypergas::Conserved<D>& c0,
                                 const hypergas::Conserved<D>& c1) {
  return {hypergas::energy_rel_drift(c0, c1), hypergas::momentum_drift(c0, c1)};
}

using test_support::for_replicas;
using test_support::mean_se;
using test_support::t_threshold;

}  // namespace extreme
