// Reference correlations of the tests: the velocity autocorrelation and the mean squared
// displacement by their defining double sums, O(n D L^2), against which the FFT versions
// (analysis/vacf.hpp) and the multiple-tau correlator are checked.
//
// Input as in analysis/vacf.hpp: `frames` frames of n particles in `dim` dimensions, frame f,
// particle i, component k at data[(f * n + i) * dim + k]; averages over all particles and all
// time origins t0 = 0 .. frames-1-lag.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace test_support {

namespace detail {
inline std::size_t channels(const std::vector<double>& data, std::size_t frames, std::size_t n,
                            int dim, std::size_t max_lag) {
  const std::size_t c = n * static_cast<std::size_t>(dim);
  if (dim < 1 || frames < 1 || n < 1 || data.size() != frames * c || max_lag >= frames)
    throw std::invalid_argument("test_support: series shape or max_lag out of range");
  return c;
}
}  // namespace detail

/// vacf(lag) = < v(t0) . v(t0 + lag) > for lags 0 .. max_lag (max_lag < frames). velocity^2.
inline std::vector<double> vacf_direct(const std::vector<double>& v, std::size_t frames,
                                       std::size_t n, int dim, std::size_t max_lag) {
  const std::size_t channels = detail::channels(v, frames, n, dim, max_lag);
  std::vector<double> acc(max_lag + 1, 0.0);
  for (std::size_t lag = 0; lag <= max_lag; ++lag) {
    for (std::size_t t = 0; t + lag < frames; ++t)
      for (std::size_t c = 0; c < channels; ++c)
        acc[lag] += v[t * channels + c] * v[(t + lag) * channels + c];
    acc[lag] /= static_cast<double>(n) * static_cast<double>(frames - lag);
  }
  return acc;
}

/// msd(lag) = < |r(t0 + lag) - r(t0)|^2 > for lags 0 .. max_lag from unwrapped positions.
/// length^2.
inline std::vector<double> msd_direct(const std::vector<double>& r, std::size_t frames,
                                      std::size_t n, int dim, std::size_t max_lag) {
  const std::size_t channels = detail::channels(r, frames, n, dim, max_lag);
  std::vector<double> acc(max_lag + 1, 0.0);
  for (std::size_t lag = 0; lag <= max_lag; ++lag) {
    for (std::size_t t = 0; t + lag < frames; ++t)
      for (std::size_t c = 0; c < channels; ++c) {
        const double d = r[(t + lag) * channels + c] - r[t * channels + c];
        acc[lag] += d * d;
      }
    acc[lag] /= static_cast<double>(n) * static_cast<double>(frames - lag);
  }
  return acc;
}

}  // namespace test_support
