// Shared helpers of the DSMC physics tests: replicas on two threads, moments, KS p-values.
#pragma once

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <thread>
#include <vector>

#include "hypergas/particles.hpp"

namespace dsmc_test {

/// Runs f(r) for r = 0..R-1 on two threads (even r here, odd r on a second thread).
/// Replicas are independent runs with their own seeds, so the statistics do not depend on
/// the scheduling; this only uses the machine's second core.
template <class F>
void for_replicas(int R, F&& f) {
  std::thread t([&] {
    for (int r = 1; r < R; r += 2) f(r);
  });
  for (int r = 0; r < R; r += 2) f(r);
  t.join();
}

/// Mean and standard error of a sample.
inline std::pair<double, double> mean_se(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  const double m = std::accumulate(x.begin(), x.end(), 0.0) / n;
  double s2 = 0.0;
  for (double v : x) s2 += (v - m) * (v - m);
  return {m, std::sqrt(s2 / (n - 1.0) / n)};
}

/// Two-sided Student-t threshold with false-failure probability p for R replicas.
inline double t_threshold(double p, int R) {
  return gsl_cdf_tdist_Qinv(0.5 * p, R - 1.0);
}

/// Mean of |v|^(2k) over particles [b, e).
template <int D, hypergas::Features F>
double moment(const hypergas::Particles<D, F>& ps, int k, std::size_t b = 0, std::size_t e = 0) {
  if (e == 0) e = ps.size();
  double s = 0.0;
  for (std::size_t i = b; i < e; ++i) s += std::pow(ps.velocity(i).squaredNorm(), k);
  return s / static_cast<double>(e - b);
}

/// Kolmogorov-Smirnov distance of sample x from `cdf`, and its p-value (asymptotic
/// Kolmogorov law with Stephens' finite-n correction).
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
