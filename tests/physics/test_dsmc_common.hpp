// Shared helpers of the DSMC physics tests: moments, KS test of speeds, exponential fits
// (replicas and t thresholds from support/statistics.hpp).
#pragma once

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <thread>
#include <vector>

#include "hypergas/particles.hpp"
#include "support/statistics.hpp"

namespace dsmc_test {

using test_support::for_replicas;
using test_support::ks;
using test_support::mean_se;
using test_support::t_threshold;

/// The statistical tests run the engine on two threads in blocks of 1024 candidates, so
/// that every path of the parallel schedule (deferred candidates, raises of the bound inside
/// a block) is under their statistics. The gas is bit for bit that of one thread
/// (tests/unit/test_dsmc_parallel.cpp), so the tests' seeds and tolerances are unchanged.
/// Replicas that run side by side (for_replicas) stay on one thread each: two teams on two
/// cores would only wait for each other.
template <class Engine>
void on_two_threads(Engine& e) {
  e.set_threads(2, 1024);
}

/// Calls f(r) for r = 0 .. R-1, one after another (each replica then uses two threads).
template <class F>
void for_replicas_in_turn(int R, F&& f) {
  for (int r = 0; r < R; ++r) f(r);
}

/// Mean of |v|^(2k) over particles [b, e).
template <int D, hypergas::Features F>
double moment(const hypergas::Particles<D, F>& ps, int k, std::size_t b = 0, std::size_t e = 0) {
  if (e == 0) e = ps.size();
  double s = 0.0;
  for (std::size_t i = b; i < e; ++i) s += std::pow(ps.velocity(i).squaredNorm(), k);
  return s / static_cast<double>(e - b);
}

/// KS distance and p-value of the speeds of particles [b, e) against the D-dimensional
/// Maxwell-Boltzmann speed law at kT/m = `kT_over_m`: |v|^2 / (kT/m) is chi-square with D
/// degrees of freedom.
template <int D, hypergas::Features F>
std::pair<double, double> ks_maxwell(const hypergas::Particles<D, F>& ps, double kT_over_m,
                                     std::size_t b = 0, std::size_t e = 0) {
  if (e == 0) e = ps.size();
  std::vector<double> sp;
  for (std::size_t i = b; i < e; ++i) sp.push_back(ps.velocity(i).squaredNorm() / kT_over_m);
  return ks(sp, [](double x) { return gsl_cdf_chisq_P(x, D); });
}

/// Least-squares fit of y_k = A exp(-lambda t_k): returns lambda (A eliminated exactly for
/// each lambda, golden-section search on [lo, hi]).
inline double fit_exponential_rate(const std::vector<double>& t, const std::vector<double>& y,
                                   double lo, double hi) {
  auto resid = [&](double lam) {
    double se = 0.0, sye = 0.0, syy = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double e = std::exp(-lam * t[k]);
      se += e * e;
      sye += y[k] * e;
      syy += y[k] * y[k];
    }
    return syy - sye * sye / se;
  };
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo, b = hi, c = b - g * (b - a), d = a + g * (b - a);
  for (int it = 0; it < 200; ++it) {
    if (resid(c) < resid(d))
      b = d;
    else
      a = c;
    c = b - g * (b - a);
    d = a + g * (b - a);
  }
  return 0.5 * (a + b);
}

}  // namespace dsmc_test
