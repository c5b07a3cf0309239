// hypergas/studies/statistics.hpp -- summaries of repeated measurements: the mean with its
// standard error (independent replicas) and the median (repeated timings).
#pragma once

#include <vector>

namespace hypergas::studies {

/// A mean and its standard error.
struct MeanSe {
  double mean = 0.0;
  double se = 0.0;
};

/// Mean m of the k values x and the standard error of the mean,
/// se = sqrt(sum (x - m)^2 / (k - 1) / k) (0 for k = 1). NaN for no values.
MeanSe mean_se(const std::vector<double>& x);

/// Median of x (the mean of the two middle values for an even count); NaN for no values.
double median(std::vector<double> x);

}  // namespace hypergas::studies
