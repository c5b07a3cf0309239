// Integrals of sampled correlation functions shared by the Green-Kubo recorders
// (transport_recorder.cpp, helfand_recorder.cpp): trapezoid sums, the automatic cut, the
// exponential tail (the mean with its standard error over error stretches is
// estimates.hpp's mean_se).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace hypergas::analysis::detail {

/// Lags of a correlation up to max_lag at spacing dt (both in the same unit), lag 0
/// included, rounded up to a multiple of 16 (the correlator's FFT blocks).
inline std::size_t lag_count(double max_lag, double dt) {
  const auto k = static_cast<std::size_t>(std::ceil(max_lag / dt - 1e-9)) + 1;
  return (k + 15) / 16 * 16;
}

/// Trapezoid integrals I(k) = int_0^{k dt} C.
inline std::vector<double> running_integral(const std::vector<double>& c, double dt) {
  std::vector<double> I(c.size(), 0.0);
  for (std::size_t k = 1; k < c.size(); ++k) I[k] = I[k - 1] + 0.5 * dt * (c[k - 1] + c[k]);
  return I;
}

/// Least-squares slope of ln c over lags first .. last (points with c > 0), negated; NaN
/// with fewer than two points.
inline double log_slope(const std::vector<double>& c, double dt, std::size_t first,
                        std::size_t last) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (std::size_t k = first; k <= last && k < c.size(); ++k) {
    if (!(c[k] > 0.0)) continue;
    const double x = static_cast<double>(k) * dt, y = std::log(c[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, m += 1;
  }
  if (m < 2) return std::numeric_limits<double>::quiet_NaN();
  return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
}

/// The automatic cut: the first lag k with k dt >= window * I(k) / C(0) (Sokal's window
/// at `window` integral times), or the last lag.
inline std::size_t auto_cut(const std::vector<double>& c, const std::vector<double>& I,
                            double dt, double window) {
  for (std::size_t k = 1; k < c.size(); ++k)
    if (static_cast<double>(k) * dt >= window * I[k] / c[0]) return k;
  return c.size() - 1;
}

/// The tail's decay rate: of ln C over lags [k / 2, k], or C(0) / I[k] if that fit fails.
inline double tail_rate(const std::vector<double>& c, const std::vector<double>& I,
                        std::size_t k, double dt) {
  const double g = log_slope(c, dt, k / 2, k);
  if (g > 0.0) return g;
  return c[0] != 0.0 && I[k] > 0.0 ? c[0] / I[k] : 0.0;
}

/// The integral of a point-sampled curve c with the cut at lag k: the trapezoid sum I[k],
/// its end corrections (Euler-Maclaurin: + h^2/12 (C'(0+) - C'(t_c)), C'(0+) from the first
/// three points, C'(t_c) from the tail), and the tail beyond t_c: C(t_c) / g for the tail's
/// decay rate g. Returns {value, tail}.
inline std::pair<double, double> cut_value(const std::vector<double>& c,
                                           const std::vector<double>& I, std::size_t k,
                                           double dt, double g) {
  const double tail = g > 0.0 ? c[k] / g : 0.0;
  const double d0 = c.size() > 2 ? (-3.0 * c[0] + 4.0 * c[1] - c[2]) / (2.0 * dt) : 0.0;
  const double dk = -(g > 0.0 ? g : 0.0) * c[k];
  return {I[k] + dt * dt / 12.0 * (d0 - dk) + tail, tail};
}

/// The integral of the flux whose interval averages have correlation c (c(l): lag l dt):
/// int_0^inf C = dt (c(0) / 2 + sum_{l >= 1} c(l)) exactly, since the triangle weights of
/// the averages sum to one; summed to the cut k, with the geometric tail
/// dt c(k) q / (1 - q), q = exp(-g dt). Returns {value, tail}.
inline std::pair<double, double> increment_value(const std::vector<double>& c, std::size_t k,
                                                 double dt, double g) {
  double sum = 0.5 * c[0];
  for (std::size_t l = 1; l <= k; ++l) sum += c[l];
  const double q = std::exp(-g * dt);
  const double tail = g > 0.0 ? dt * c[k] * q / (1.0 - q) : 0.0;
  return {dt * sum + tail, tail};
}

}  // namespace hypergas::analysis::detail
