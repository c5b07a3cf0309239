// Shared helpers of the extreme-case tests: finiteness, conservation, replica statistics.
#pragma once

#include <gsl/gsl_cdf.h>

#include <cmath>
#include <cstddef>
#include <numeric>
#include <thread>
#include <utility>
#include <vector>

#include "hypergas/dsmc/conserved.hpp"
#include "hypergas/particles.hpp"

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
std::pair<double, double> drifts(const hypergas::dsmc::Conserved<D>& c0,
                                 const hypergas::dsmc::Conserved<D>& c1) {
  return {std::abs(c1.energy - c0.energy) / c0.energy,
          (c1.momentum - c0.momentum).norm() / c0.momentum_scale};
}

/// Runs f(r) for r = 0..R-1 on two threads (independent replicas, own seeds).
template <class Fn>
void for_replicas(int R, Fn&& f) {
  std::thread t([&] {
    for (int r = 1; r < R; r += 2) f(r);
  });
  for (int r = 0; r < R; r += 2) f(r);
  t.join();
}

/// Mean and standard error of the mean of a sample.
inline std::pair<double, double> mean_se(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  const double m = std::accumulate(x.begin(), x.end(), 0.0) / n;
  double s2 = 0.0;
  for (double v : x) s2 += (v - m) * (v - m);
  return {m, std::sqrt(s2 / (n - 1.0) / n)};
}

/// Two-sided Student-t threshold with false-failure probability p for R replicas.
inline double t_threshold(double p, int R) { return gsl_cdf_tdist_Qinv(0.5 * p, R - 1.0); }

}  // namespace extreme
