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

Moments moments_from_sums(int dim, double m_mean, const PowerSums& p, double scale) {
  if (!(p.n >= 2.0))
    throw InvalidInput("compute_moments: need at least 2 particles, got " +
                       std::to_string(static_cast<std::size_t>(p.n)));
  Moments m;
  const double n = p.n;
  m.n = static_cast<std::size_t>(n);
  const double s2 = scale * scale, s4 = s2 * s2, s6 = s4 * s2;
  const auto scaled = [](Estimate e, double f) { return Estimate{e.value * f, e.error * f}; };
  const double kT = p.twice_e / (dim * n);  // in the sums' units
  m.kT = kT * s2;
  m.m2 = scaled(mean_estimate(p.s2, p.s4, n), s2);
  m.m4 = scaled(mean_estimate(p.s4, p.s8, n), s4);
  m.m6 = scaled(mean_estimate(p.s6, p.s12, n), s6);
  // Kurtosis K = a / b^2, a = <x^4>, b = <x^2>. Delta method:
  // Var K = [Var(x^4)/b^4 - 4 a Cov(x^4, x^2)/b^5 + 4 a^2 Var(x^2)/b^6] / n.
  const double a = p.x4 / n, b = p.x2 / n;
  if (b > 0.0) {
    const double var_a = p.x8 / n - a * a, var_b = p.x4 / n - b * b, cov = p.x6 / n - a * b;
    const double var_k = (var_a / std::pow(b, 4) - 4.0 * a * cov / std::pow(b, 5) +
                          4.0 * a * a * var_b / std::pow(b, 6)) /
                         (n - 1.0);
    m.kurtosis_x = {a / (b * b), std::sqrt(std::max(var_k, 0.0))};
  } else {
    m.kurtosis_x = {NAN, NAN};
  }
  const double kt_m = kT / m_mean, norm = dim * (dim + 2.0) * kt_m * kt_m;
  const Estimate w = mean_estimate(p.w4, p.w8, n);
  m.m4_ratio = norm > 0.0 ? Estimate{w.value / norm, w.error / norm} : Estimate{NAN, NAN};
  return m;
}

Moments MomentSums::result(Summation how) const {
  if (n_ < 2)
    throw InvalidInput("compute_moments: need at least 2 particles, got " + std::to_string(n_));
  const auto sum = [how](const RunningSum& r) { return r.value(how); };
  PowerSums p;
  p.n = static_cast<double>(n_);
  p.s2 = sum(s2_), p.s4 = sum(s4_), p.s6 = sum(s6_), p.s8 = sum(s8_), p.s12 = sum(s12_);
  p.w4 = sum(w4_), p.w8 = sum(w8_);
  p.x2 = sum(x2_), p.x4 = sum(x4_), p.x6 = sum(x6_), p.x8 = sum(x8_);
  p.twice_e = sum(twice_e_);
  return moments_from_sums(dim_, m_mean_, p);
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
