// The estimates of repeated measurements (analysis/estimates.hpp): mean and standard error
// with their small-sample behaviour, block averages, and the least-squares line slope
// (analysis/fit.hpp) on exact data. Deterministic.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hypergas/analysis/estimates.hpp"
#include "hypergas/analysis/fit.hpp"

using namespace hypergas::analysis;

TEST_CASE("mean_se: no value, one value, two values", "[estimates]") {
  const MeanSe none = mean_se({});
  CHECK(std::isnan(none.mean));
  CHECK(std::isnan(none.se));
  const MeanSe one = mean_se({2.5});
  CHECK(one.mean == 2.5);
  CHECK(std::isnan(one.se));
  // two values: mean 2, deviations +-1: se = sqrt(2 / 1 / 2) = 1
  const MeanSe two = mean_se({1.0, 3.0});
  CHECK(two.mean == 2.0);
  CHECK(two.se == 1.0);
}

TEST_CASE("mean_se: a known case, and the summation order", "[estimates]") {
  // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, sum of squared deviations 32, s^2 = 32/7,
  // se = sqrt(32 / 7 / 8)
  const std::vector<double> x{2, 4, 4, 4, 5, 5, 7, 9};
  const MeanSe r = mean_se(x);
  CHECK(r.mean == 5.0);
  CHECK(r.se == Approx(std::sqrt(32.0 / 7.0 / 8.0)).epsilon(1e-15));
  // the mean is summed as x_i / k (bit for bit what the run summaries always wrote)
  const std::vector<double> y{0.1, 0.2, 0.7};
  double m = 0.0;
  for (double v : y) m += v / 3.0;
  CHECK(mean_se(y).mean == m);
}

TEST_CASE("Block averages: block means, the rest left out, and their standard error",
          "[estimates]") {
  // rows 10 .. 19 of 0, 1, 2, ...: 3 blocks of 3 rows (the tenth row left out)
  std::vector<double> y;
  for (int i = 0; i < 20; ++i) y.push_back(i);
  const std::vector<double> b = block_means(y, 10, 20, 3);
  REQUIRE(b.size() == 3);
  CHECK(b[0] == 11.0);
  CHECK(b[1] == 14.0);
  CHECK(b[2] == 17.0);
  const MeanSe a = block_average(y, 10, 20, 3);
  CHECK(a.mean == Approx(14.0).epsilon(1e-15));
  // deviations -3, 0, 3: s^2 = 18 / 2 = 9, se = 3 / sqrt(3)
  CHECK(a.se == Approx(std::sqrt(3.0)).epsilon(1e-14));
  // over_blocks gives f of each block
  const MeanSe w = over_blocks(10, 20, 3, [](std::size_t i, std::size_t e) {
    return static_cast<double>(e - i);
  });
  CHECK(w.mean == 3.0);
  CHECK(w.se == 0.0);
  CHECK(range_mean(y, 0, 4) == 1.5);
}

TEST_CASE("Line slope: exact on a straight line, weighted or not", "[estimates]") {
  std::vector<double> x, y, w;
  for (int i = 0; i < 10; ++i) {
    x.push_back(0.5 * i);
    y.push_back(3.0 - 2.0 * x.back());
    w.push_back(1.0 + i);
  }
  CHECK(line_slope(x, y, 0, x.size()) == Approx(-2.0).epsilon(1e-14));
  CHECK(line_slope(x, y, 2, 7) == Approx(-2.0).epsilon(1e-14));
  CHECK(line_slope(x, y, 0, x.size(), w) == Approx(-2.0).epsilon(1e-14));
  // x that do not vary: no slope
  CHECK(std::isnan(line_slope(std::vector<double>(4, 1.0), y, 0, 4)));
}
