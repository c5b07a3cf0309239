// hypergas/studies/statistics.hpp -- the median of repeated timings. (The mean of repeated
// measurements with its standard error is analysis/estimates.hpp's mean_se.)
#pragma once

#include <vector>

namespace hypergas::studies {

/// Median of x (the mean of the two middle values for an even count); NaN for no values.
double median(std::vector<double> x);

}  // namespace hypergas::studies
