// Statistical tests of rng.hpp and sampling.hpp. Every test uses a fixed seed, so it is
// deterministic; the stated false-failure probability is the chance that a correct sampler
// with an arbitrary seed would fail, i.e. how unlucky the fixed seed would have to be.
#include <catch2/catch.hpp>

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "support/statistics.hpp"
#include "hypergas/geometry.hpp"
#include "hypergas/sampling.hpp"

using namespace hypergas;

using test_support::ks_pvalue;

namespace {
constexpr int n_samples = 200000;
}  // namespace

TEMPLATE_TEST_CASE_SIG("unit vectors: unit length, zero mean, covariance I/D", "[sampling]",
                       ((int D), D), 1, 2, 3, 4, 5, 6) {
  Rng rng(2024, D);
  Vec<D> mean = Vec<D>::Zero();
  Eigen::Matrix<double, D, D> cov = Eigen::Matrix<double, D, D>::Zero();
  std::vector<double> first;
  for (int i = 0; i < n_samples; ++i) {
    const Vec<D> n = unit_vector<D>(rng);
    REQUIRE(std::abs(n.squaredNorm() - 1.0) <= 4e-16 * D);
    mean += n;
    cov += n * n.transpose();
    first.push_back(n[0]);
  }
  mean /= n_samples;
  cov /= n_samples;
  // Each mean component has variance 1/(D N); off-diagonal second moments E[n_i n_j] have
  // variance 1/(D(D+2) N); diagonal ones 3/(D(D+2)) - 1/D^2 per sample. Each entry is
  // checked as |z| < 5 (two-sided p = 5.7e-7); with at most 27 entries the false-failure
  // probability of the whole test is below 2e-5 (Bonferroni).
  const double sd_mean = std::sqrt(1.0 / (D * double(n_samples)));
  const double sd_off = std::sqrt(1.0 / (D * (D + 2.0) * n_samples));
  const double var_diag = 3.0 / (D * (D + 2.0)) - 1.0 / (double(D) * D);
  for (int i = 0; i < D; ++i) {
    REQUIRE(std::abs(mean[i]) < 5 * sd_mean);
    for (int j = 0; j < D; ++j) {
      if (i != j)
        REQUIRE(std::abs(cov(i, j)) < 5 * sd_off);
      else if (D == 1)
        REQUIRE(cov(i, i) == 1.0);
      else
        REQUIRE(std::abs(cov(i, i) - 1.0 / D) < 5 * std::sqrt(var_diag / n_samples));
    }
  }
  // Goodness of fit of one component: (n_x + 1)/2 ~ Beta((D-1)/2, (D-1)/2) for D >= 2.
  // KS p-value must exceed 1e-4 (false-failure probability 1e-4).
  if constexpr (D >= 2) {
    const double a = 0.5 * (D - 1);
    const double p =
        ks_pvalue(first, [a](double x) { return gsl_cdf_beta_P(0.5 * (x + 1.0), a, a); });
    INFO("KS p-value " << p);
    REQUIRE(p > 1e-4);
  } else {
    // D = 1: a fair sign. Binomial z-test, |z| < 5 (false failure 5.7e-7).
    const double plus = std::count(first.begin(), first.end(), 1.0);
    REQUIRE(std::abs(plus - 0.5 * n_samples) < 5 * std::sqrt(0.25 * n_samples));
  }
}

TEMPLATE_TEST_CASE_SIG("hard-sphere normal: cos(theta) density ~ cos(theta) on the hemisphere",
                       "[sampling]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  Rng rng(77, D);
  std::vector<double> t;
  Vec<D> tangential_mean = Vec<D>::Zero();
  const Vec<D> g = 3.0 * normal_vector<D>(rng);  // a fixed, arbitrary relative velocity
  const Vec<D> gh = g.normalized();
  for (int i = 0; i < n_samples; ++i) {
    const Vec<D> n = hard_sphere_normal<D>(rng, g);
    REQUIRE(std::abs(n.squaredNorm() - 1.0) <= 4e-16 * D);
    const double c = n.dot(gh);
    REQUIRE(c >= 0.0);
    t.push_back(c);
    tangential_mean += n - c * gh;
  }
  if constexpr (D == 1) {
    REQUIRE(std::all_of(t.begin(), t.end(), [](double c) { return c == 1.0; }));
  } else {
    // CDF of t = g_hat.n: F(t) = 1 - (1 - t^2)^((D-1)/2) (derivation in sampling.hpp).
    // KS p-value > 1e-4: false-failure probability 1e-4.
    const double p =
        ks_pvalue(t, [](double x) { return 1.0 - std::pow(1.0 - x * x, 0.5 * (D - 1)); });
    INFO("KS p-value " << p);
    REQUIRE(p > 1e-4);
    // The tangential part is isotropic: its mean vanishes. Each component has variance
    // <= 1/N, |mean| < 5/sqrt(N) per component (false failure < 6 * 5.7e-7).
    tangential_mean /= n_samples;
    REQUIRE(tangential_mean.cwiseAbs().maxCoeff() < 5.0 / std::sqrt(double(n_samples)));
    // Mean of t: E[t] = Gamma-function ratio; compare with the exact integral
    // E[t] = int t f(t) dt computed from the CDF by the identity E[t] = int_0^1 (1 - F) dt.
    double et = 0.0;
    const int m = 200000;
    for (int k = 0; k < m; ++k) {
      const double x = (k + 0.5) / m;
      et += std::pow(1.0 - x * x, 0.5 * (D - 1)) / m;
    }
    double mean_t = 0.0, m2 = 0.0;
    for (double c : t) mean_t += c, m2 += c * c;
    mean_t /= n_samples;
    const double sd = std::sqrt((m2 / n_samples - mean_t * mean_t) / n_samples);
    REQUIRE(std::abs(mean_t - et) < 5 * sd);
  }
}

TEST_CASE("hard-sphere normal for extreme and zero relative velocities", "[sampling]") {
  Rng rng(5);
  for (double s : {1e-300, 1e-150, 1e150, 1e300}) {
    const Vec<3> g = s * Vec<3>(1.0, -2.0, 0.5);
    const Vec<3> n = hard_sphere_normal<3>(rng, g);
    REQUIRE(n.allFinite());
    REQUIRE(std::abs(n.squaredNorm() - 1.0) < 1e-15);
    REQUIRE(n.dot(g) > 0.0);
  }
  const Vec<4> n0 = hard_sphere_normal<4>(rng, Vec<4>::Zero());
  REQUIRE(std::abs(n0.squaredNorm() - 1.0) < 1e-15);
}

TEST_CASE("rng: reproducible, splittable, uniform and unbiased", "[rng]") {
  Rng a(42), b(42), c(42, 1);
  for (int i = 0; i < 100; ++i) REQUIRE(a() == b());
  int same = 0;
  Rng a2(42);
  for (int i = 0; i < 100; ++i) same += (a2() == c());
  REQUIRE(same == 0);
  // split(k) is deterministic and distinct for distinct k.
  REQUIRE(Rng(9).split(3)() == Rng(9).split(3)());
  REQUIRE(Rng(9).split(3)() != Rng(9).split(4)());

  // below(n): chi-square over 10 cells with N = 1e6; threshold = upper 1e-5 quantile of
  // chi-square(9) (false failure 1e-5).
  Rng r(1);
  std::vector<double> cells(10, 0.0);
  const int n = 1000000;
  for (int i = 0; i < n; ++i) cells[r.below(10)] += 1.0;
  double chi2 = 0.0;
  for (double o : cells) chi2 += (o - n / 10.0) * (o - n / 10.0) / (n / 10.0);
  REQUIRE(chi2 < gsl_cdf_chisq_Qinv(1e-5, 9));

  // Normal deviates: mean, variance and fourth moment within 5 standard errors.
  double s1 = 0, s2 = 0, s4 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = r.normal();
    s1 += x, s2 += x * x, s4 += x * x * x * x;
  }
  REQUIRE(std::abs(s1 / n) < 5 * std::sqrt(1.0 / n));
  REQUIRE(std::abs(s2 / n - 1.0) < 5 * std::sqrt(2.0 / n));
  REQUIRE(std::abs(s4 / n - 3.0) < 5 * std::sqrt(96.0 / n));  // Var(x^4) = 105 - 9
  // Uniform in [0,1): mean 1/2 (sd sqrt(1/12/n)).
  double su = 0;
  for (int i = 0; i < n; ++i) su += r.uniform();
  REQUIRE(std::abs(su / n - 0.5) < 5 * std::sqrt(1.0 / 12.0 / n));
}

TEST_CASE("unit-ball volumes match the known values in D = 1..3", "[geometry]") {
  REQUIRE(unit_ball_volume(1) == Approx(2.0).epsilon(1e-15));
  REQUIRE(unit_ball_volume(2) == Approx(M_PI).epsilon(1e-15));
  REQUIRE(unit_ball_volume(3) == Approx(4.0 * M_PI / 3.0).epsilon(1e-15));
  REQUIRE(unit_sphere_area(3) == Approx(4.0 * M_PI).epsilon(1e-15));
  REQUIRE(ball_volume(3, 1.0) == Approx(M_PI / 6.0).epsilon(1e-15));
}
