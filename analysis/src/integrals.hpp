// Integrals of sampled correlation functions shared by the Green-Kubo recorders
// (transport_recorder.cpp, helfand_recorder.cpp): trapezoid sums, the automatic cut, the
// exponential tail (the mean with its standard error over error stretches is
// estimates.hpp's mean_se).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "hypergas/analysis/estimates.hpp"

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

/// The Green-Kubo integral read from a running integral at its plateau, with the error of
/// the cut measured: the one rule of every EDMD transport coefficient
/// (helfand_recorder.cpp).
///
/// I[k] is the running integral of the whole run at lag k, Ij[j][k] the same of error
/// stretch j. The candidate cuts are k0 and on by factors of sqrt(2) up to k_max. At a cut k
/// the drifts over the last two doublings, d1 = I[k/2] - I[k/4] and d2 = I[k] - I[k/2],
/// give the decay of the running integral's increments, q = d2 / d1 per doubling. If they
/// keep falling by q, the part of the integral beyond k that the run did not see is
/// r = d2 q / (1 - q). A correlation that decays as t^(-p) has q = 2^(1 - p) exactly, and
/// then r = d2 / (2^(p - 1) - 1); an exponential decay has q near 0 and leaves r near 0. The
/// slowest decay a fluid has is the hydrodynamic long-time tail, p = D / 2 (Alder &
/// Wainwright, Phys. Rev. A 1, 18 (1970)), so q is clamped to [0, 2^(1 - D/2)]: at most
/// r = 2.41 d2 in 3D, d2 in 4D, 0.55 d2 in 5D, 0.33 d2 in 6D. 2D, whose tail integral
/// diverges logarithmically until the periodic box cuts it off, takes the 3D bound. The
/// value is I[k_c] + r(k_c). Each stretch is extrapolated with the whole run's q, so the
/// statistical error s is that of the extrapolated value. The truncation error is
/// |r(k_c)|, the whole correction, since the tail's form is measured only through q. The
/// drift is measured with noise, so the cut k_c is the candidate that minimises the stated
/// error sqrt(s^2 + r^2): s grows with the cut, r falls with it. reached says whether
/// |r(k_c)| <= s(k_c), a plateau as far as the run can tell.
struct Plateau {
  double value = std::numeric_limits<double>::quiet_NaN();
  double statistical_error = std::numeric_limits<double>::quiet_NaN();
  double truncation_error = std::numeric_limits<double>::quiet_NaN();
  double error = std::numeric_limits<double>::quiet_NaN();
  double remainder = 0.0;  ///< r(k_c), included in value
  double factor = 0.0;     ///< q / (1 - q) at k_c
  std::size_t cut = 0;
  bool reached = false;           ///< the remainder is within the statistical error
  std::vector<double> stretches;  ///< the stretches' extrapolated values at k_c
};

/// The largest decay of the increments per doubling, 2^(1 - p) with p = D/2 (3D's in 2D).
inline double max_decay(int dim) { return std::pow(2.0, 1.0 - (dim >= 3 ? 0.5 * dim : 1.5)); }

/// q / (1 - q) of the running integral I at cut k (Plateau's comment).
inline double tail_factor(const std::vector<double>& I, std::size_t k, int dim) {
  if (k < 4) return 0.0;
  const double d1 = I[k / 2] - I[k / 4], d2 = I[k] - I[k / 2];
  const double q = d1 != 0.0 ? std::clamp(d2 / d1, 0.0, max_decay(dim)) : 0.0;
  return q / (1.0 - q);
}

/// I[k] + f (I[k] - I[k / 2]): a running integral at cut k with the remainder of a tail
/// whose increments fall as the whole run's (factor f = tail_factor of the run).
inline double extrapolated(const std::vector<double>& I, std::size_t k, double f) {
  return I[k] + f * (I[k] - I[k / 2]);
}

/// The plateau of the running integral I (Plateau's comment): candidate cuts from k0 to
/// k_max, error stretches Ij, dimension D for the slowest tail.
inline Plateau plateau(const std::vector<double>& I, const std::vector<std::vector<double>>& Ij,
                       std::size_t k0, std::size_t k_max, int dim) {
  Plateau r;
  if (I.empty()) return r;
  k_max = std::min(k_max, I.size() - 1);
  k0 = std::max<std::size_t>(1, std::min(k0, k_max));
  // the extrapolated values of the stretches at cut k
  const auto stretch_values = [&](std::size_t k) {
    const double f = tail_factor(I, k, dim);
    std::vector<double> x;
    for (const auto& s : Ij) x.push_back(extrapolated(s, k, f));
    return x;
  };
  const auto se_at = [&](std::size_t k) { return mean_se(stretch_values(k)).se; };
  const auto remainder = [&](std::size_t k) {
    return extrapolated(I, k, tail_factor(I, k, dim)) - I[k];
  };
  std::size_t cut = std::max<std::size_t>(2, k0);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = cut; k <= k_max;
       k = std::max(k + 1, static_cast<std::size_t>(std::ceil(std::sqrt(2.0) * double(k))))) {
    const double e = std::hypot(se_at(k), remainder(k));
    if (e < best) best = e, cut = k;
  }
  cut = std::min(cut, k_max);
  r.cut = cut;
  r.factor = tail_factor(I, cut, dim);
  r.remainder = remainder(cut);
  r.value = I[cut] + r.remainder;
  r.stretches = stretch_values(cut);
  r.statistical_error = mean_se(r.stretches).se;
  r.truncation_error = std::fabs(r.remainder);
  r.error = std::hypot(r.statistical_error, r.truncation_error);
  r.reached = r.truncation_error <= r.statistical_error;
  return r;
}

}  // namespace hypergas::analysis::detail
