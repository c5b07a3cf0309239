// Velocity moments with standard errors (sample variances of the per-particle powers; the
// kurtosis error by the delta method).
#include "hypergas/analysis/moments.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "hypergas/error.hpp"

namespace hypergas::analysis {

namespace {
// Mean and standard error of the mean from sums of x and x^2 over n values.
Estimate mean_estimate(double sum, double sum_sq, double n) {
  const double mean = sum / n;
  const double var = std::max(sum_sq / n - mean * mean, 0.0) * n / (n - 1.0);
  return {mean, std::sqrt(var / n)};
}
}  // namespace

Moments MomentSums::result(Summation how) const {
  if (n_ < 2)
    throw InvalidInput("compute_moments: need at least 2 particles, got " + std::to_string(n_));
  Moments m;
  m.n = n_;
  const double n = static_cast<double>(n_);
  const auto sum = [how](const RunningSum& r) { return r.value(how); };
  m.kT = sum(twice_e_) / (dim_ * n);
  m.m2 = mean_estimate(sum(s2_), sum(s4_), n);
  m.m4 = mean_estimate(sum(s4_), sum(s8_), n);
  m.m6 = mean_estimate(sum(s6_), sum(s12_), n);
  // Kurtosis K = a / b^2, a = <x^4>, b = <x^2>. Delta method:
  // Var K = [Var(x^4)/b^4 - 4 a Cov(x^4, x^2)/b^5 + 4 a^2 Var(x^2)/b^6] / n.
  const double a = sum(x4_) / n, b = sum(x2_) / n;
  if (b > 0.0) {
    const double var_a = sum(x8_) / n - a * a, var_b = sum(x4_) / n - b * b,
                 cov = sum(x6_) / n - a * b;
    const double var_k = (var_a / std::pow(b, 4) - 4.0 * a * cov / std::pow(b, 5) +
                          4.0 * a * a * var_b / std::pow(b, 6)) /
                         (n - 1.0);
    m.kurtosis_x = {a / (b * b), std::sqrt(std::max(var_k, 0.0))};
  } else {
    m.kurtosis_x = {NAN, NAN};
  }
  const double kt_m = m.kT / m_mean_, norm = dim_ * (dim_ + 2.0) * kt_m * kt_m;
  const Estimate w = mean_estimate(sum(w4_), sum(w8_), n);
  m.m4_ratio = norm > 0.0 ? Estimate{w.value / norm, w.error / norm} : Estimate{NAN, NAN};
  return m;
}

Moments compute_moments(const Snapshot& s, int species, Summation how) {
  validate(s);
  const std::size_t n = count(s, species);
  if (n < 2)
    throw InvalidInput("compute_moments: need at least 2 particles, got " + std::to_string(n));
  MomentSums sums(s.dim, mean_mass(s, species, how));
  const auto stride = static_cast<std::size_t>(s.stride);
  for (std::size_t i = 0; i < s.n; ++i) {
    if (species >= 0 && (s.species ? s.species[i] : 0) != species) continue;
    sums.add(s.velocities + i * stride, s.inverse_mass(i));
  }
  return sums.result(how);
}

}  // namespace hypergas::analysis
