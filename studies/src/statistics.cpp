// Median of repeated timings.
#include "hypergas/studies/statistics.hpp"

#include <algorithm>
#include <limits>

namespace hypergas::studies {

double median(std::vector<double> x) {
  if (x.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(x.begin(), x.end());
  const std::size_t m = x.size() / 2;
  return x.size() % 2 ? x[m] : 0.5 * (x[m - 1] + x[m]);
}

}  // namespace hypergas::studies
