// Velocity moments with standard errors (sample variances of the per-particle powers; the
// kurtosis error by the delta method).
#include "hypergas/analysis/moments.hpp"

#include <cmath>
#include <string>

#include "hypergas/analysis/sample.hpp"
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

Moments compute_moments(const Snapshot& s, int species) {
  validate(s);
  Moments m;
  m.n = count(s, species);
  if (m.n < 2)
    throw InvalidInput("compute_moments: need at least 2 particles, got " + std::to_string(m.n));
  const double m_mean = mean_mass(s, species);
  // Power sums: raw |v|^2k (k = 1..3, and squares), mass-weighted |w|^4 and w_x^2, w_x^4, ...
  double s2 = 0, s4 = 0, s6 = 0, s8 = 0, s12 = 0;
  double w4 = 0, w8 = 0, x2 = 0, x4 = 0, x6 = 0, x8 = 0, twice_e = 0;
  const auto stride = static_cast<std::size_t>(s.stride);
  for (std::size_t i = 0; i < s.n; ++i) {
    if (species >= 0 && (s.species ? s.species[i] : 0) != species) continue;
    const double* v = s.velocities + i * stride;
    double vv = 0.0;
    for (int k = 0; k < s.dim; ++k) vv += v[k] * v[k];
    const double inv_m = s.inverse_mass(i);
    const double f = 1.0 / (inv_m * m_mean);  // w = v sqrt(f)
    const double v4 = vv * vv, v6 = v4 * vv;
    s2 += vv;
    s4 += v4;
    s6 += v6;
    s8 += v4 * v4;
    s12 += v6 * v6;
    const double ww4 = v4 * f * f;
    w4 += ww4;
    w8 += ww4 * ww4;
    const double xx = v[0] * v[0] * f;
    x2 += xx;
    x4 += xx * xx;
    x6 += xx * xx * xx;
    x8 += xx * xx * xx * xx;
    twice_e += vv / inv_m;
  }
  const double n = static_cast<double>(m.n);
  m.kT = twice_e / (s.dim * n);
  m.m2 = mean_estimate(s2, s4, n);
  m.m4 = mean_estimate(s4, s8, n);
  m.m6 = mean_estimate(s6, s12, n);
  // Kurtosis K = a / b^2, a = <x^4>, b = <x^2>. Delta method:
  // Var K = [Var(x^4)/b^4 - 4 a Cov(x^4, x^2)/b^5 + 4 a^2 Var(x^2)/b^6] / n.
  const double a = x4 / n, b = x2 / n;
  if (b > 0.0) {
    const double var_a = x8 / n - a * a, var_b = x4 / n - b * b, cov = x6 / n - a * b;
    const double var_k = (var_a / std::pow(b, 4) - 4.0 * a * cov / std::pow(b, 5) +
                          4.0 * a * a * var_b / std::pow(b, 6)) /
                         (n - 1.0);
    m.kurtosis_x = {a / (b * b), std::sqrt(std::max(var_k, 0.0))};
  } else {
    m.kurtosis_x = {NAN, NAN};
  }
  const double kt_m = m.kT / m_mean, norm = s.dim * (s.dim + 2.0) * kt_m * kt_m;
  const Estimate w = mean_estimate(w4, w8, n);
  m.m4_ratio = norm > 0.0 ? Estimate{w.value / norm, w.error / norm} : Estimate{NAN, NAN};
  return m;
}

}  // namespace hypergas::analysis
