// Mean, standard error of the mean, median.
#include "hypergas/studies/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hypergas::studies {

MeanSe mean_se(const std::vector<double>& x) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (x.empty()) return {nan, nan};
  const double k = static_cast<double>(x.size());
  double m = 0.0, v = 0.0;
  for (double xi : x) m += xi / k;
  for (double xi : x) v += (xi - m) * (xi - m);
  return {m, x.size() > 1 ? std::sqrt(v / (k - 1.0) / k) : 0.0};
}

double median(std::vector<double> x) {
  if (x.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(x.begin(), x.end());
  const std::size_t m = x.size() / 2;
  return x.size() % 2 ? x[m] : 0.5 * (x[m - 1] + x[m]);
}

}  // namespace hypergas::studies
