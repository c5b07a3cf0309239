// hypergas/analysis/estimates.hpp -- the mean of repeated measurements with its standard
// error, and block averages of a time series: the one definition that the recorders, the
// run summaries, the studies, the examples and the tests use.
//
// Independent values (replicas, or blocks of a series long against its correlation time)
// x_1 .. x_k give the mean m and the standard error of the mean
//
//     m = sum_i (x_i / k),     se = sqrt(sum_i (x_i - m)^2 / (k - 1) / k),
//
// summed in that order (the mean as a sum of x_i / k, then the squared deviations), so
// that every caller's numbers are the same bit for bit. Small samples:
//   k = 0: mean NaN, se NaN;
//   k = 1: mean x_1, se NaN (one value says nothing about its scatter; a caller that
//          reports 0 there says so at its call site).
// Header-only (no GSL, no FFTW): the header-only tests use it as well.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace hypergas::analysis {

/// A mean and its standard error (NaN where undefined, see the file comment).
struct MeanSe {
  double mean = std::numeric_limits<double>::quiet_NaN();
  double se = std::numeric_limits<double>::quiet_NaN();
};

/// Mean of the values x and its standard error (file comment; NaN se for fewer than 2).
inline MeanSe mean_se(const std::vector<double>& x) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (x.empty()) return {nan, nan};
  const double k = static_cast<double>(x.size());
  double m = 0.0, v = 0.0;
  for (double xi : x) m += xi / k;
  if (x.size() < 2) return {m, nan};
  for (double xi : x) v += (xi - m) * (xi - m);
  return {m, std::sqrt(v / (k - 1.0) / k)};
}

/// Mean of y over the rows [b, e): the sum divided by e - b (NaN for an empty range).
inline double range_mean(const std::vector<double>& y, std::size_t b, std::size_t e) {
  double s = 0.0;
  for (std::size_t i = b; i < e; ++i) s += y[i];
  return s / static_cast<double>(e - b);
}

/// The rows [b, e) cut into `blocks` consecutive blocks of equal length
/// len = (e - b) / blocks (the last (e - b) % blocks rows are left out): f(i, j) for each
/// block [i, j), in order.
template <class F>
std::vector<double> per_block(std::size_t b, std::size_t e, std::size_t blocks, F&& f) {
  std::vector<double> v;
  v.reserve(blocks);
  const std::size_t len = blocks ? (e - b) / blocks : 0;
  for (std::size_t k = 0; k < blocks; ++k) v.push_back(f(b + k * len, b + (k + 1) * len));
  return v;
}

/// Block estimate: mean_se of one value per block of [b, e) (per_block), f(i, j) a block
/// mean, a slope fitted over the block, ...
template <class F>
MeanSe over_blocks(std::size_t b, std::size_t e, std::size_t blocks, F&& f) {
  return mean_se(per_block(b, e, blocks, f));
}

/// The means of y over the `blocks` consecutive blocks of [b, e) (as per_block).
inline std::vector<double> block_means(const std::vector<double>& y, std::size_t b,
                                       std::size_t e, std::size_t blocks) {
  return per_block(b, e, blocks,
                   [&](std::size_t i, std::size_t j) { return range_mean(y, i, j); });
}

/// Block average of y over [b, e): mean_se of its block_means, the standard error of a
/// correlated series' mean when the blocks are longer than its correlation time.
inline MeanSe block_average(const std::vector<double>& y, std::size_t b, std::size_t e,
                            std::size_t blocks) {
  return mean_se(block_means(y, b, e, blocks));
}

}  // namespace hypergas::analysis
