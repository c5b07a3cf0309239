// Shared statistics of the tests: replicas on two threads, mean and standard error
// (analysis/estimates.hpp, header-only), the Student-t threshold and the Kolmogorov-Smirnov test.
#pragma once

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <thread>
#include <utility>
#include <vector>

#include "hypergas/analysis/estimates.hpp"

namespace test_support {

/// Runs f(r) for r = 0..R-1 on two threads (even r here, odd r on a second thread).
/// Replicas are independent runs with their own seeds, so the statistics do not depend on
/// the scheduling; this only uses the machine's second core. No Catch2 assertions in f.
template <class F>
void for_replicas(int R, F&& f) {
  std::thread t([&] {
    for (int r = 1; r < R; r += 2) f(r);
  });
  for (int r = 0; r < R; r += 2) f(r);
  t.join();
}

/// Mean and standard error of the mean (the analysis library's header-only definition).
using hypergas::analysis::mean_se;

/// Two-sided Student-t threshold with false-failure probability p for R replicas.
inline double t_threshold(double p, int R) { return gsl_cdf_tdist_Qinv(0.5 * p, R - 1.0); }

/// Kolmogorov-Smirnov distance of sample x from the continuous CDF `cdf`, and its two-sided
/// p-value (asymptotic Kolmogorov law with Stephens' finite-n correction).
inline std::pair<double, double> ks(std::vector<double> x,
                                    const std::function<double(double)>& cdf) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = cdf(x[i]);
    d = std::max({d, (i + 1) / n - f, f - i / n});
  }
  const double lambda = (std::sqrt(n) + 0.12 + 0.11 / std::sqrt(n)) * d;
  double q = 0.0;
  for (int k = 1; k <= 100; ++k)
    q += 2.0 * ((k % 2) ? 1.0 : -1.0) * std::exp(-2.0 * k * k * lambda * lambda);
  return {d, std::clamp(q, 0.0, 1.0)};
}

/// The p-value of ks().
inline double ks_pvalue(std::vector<double> x, const std::function<double(double)>& cdf) {
  return ks(std::move(x), cdf).second;
}

}  // namespace test_support
