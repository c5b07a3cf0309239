// Goodness of fit against Maxwell–Boltzmann (analysis/statistics.hpp, sample.hpp): true MB
// samples pass, deliberately wrong distributions fail, in D = 1..6.
//
// False-failure budget: each "passes" check is p > 1e-4, and under the null hypothesis a
// p-value is (close to) uniform, so each fails with probability ~1e-4; the file makes 6 * 3
// KS + 6 * 3 chi-square + 4 mixture checks = 40 such checks, total <= 4e-3 for an arbitrary
// seed (the seeds are fixed, so the test is deterministic). The "fails" checks need
// p < 1e-10; they test the power of the tests (for N = 1e5 the deviations below are tens of
// standard errors, so the p-values are far below 1e-10).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/analysis/statistics.hpp"
#include "hypergas/error.hpp"
#include "test_analysis_support.hpp"

using namespace hypergas;
using namespace hypergas::analysis;

namespace {
constexpr std::size_t n_samples = 100000;
constexpr std::size_t bins = 50;
}  // namespace

TEST_CASE("MB samples pass KS and chi-square against the known reference", "[analysis]") {
  for (int d = 1; d <= 6; ++d) {
    test::OwnedState st(d, n_samples);
    Rng rng(11, d);
    test::fill_maxwell(st, rng, 1.3);
    const Snapshot s = st.snapshot();
    for (Quantity q : {Quantity::speed, Quantity::component, Quantity::energy}) {
      INFO("D = " << d << ", " << to_string(q));
      const MaxwellReference ref{q, d, 1.3, 1.0};  // the true parameters: no fitted parameter
      const std::vector<double> x = values(s, q);
      const TestResult ks = ks_test(x, ref);
      const Histogram h = make_histogram(x, ref, bins);
      const TestResult chi = chi_square_test(h, ref, 0);
      INFO("KS D_n " << ks.statistic << " p " << ks.p_value << "; chi2 " << chi.statistic << "/"
                     << chi.dof << " p " << chi.p_value);
      CHECK(ks.p_value > 1e-4);
      CHECK(chi.p_value > 1e-4);
      // L1: E|p_i - P_i| <= sqrt(P_i / N), so E[L1] <= sqrt(B' / N) by Cauchy–Schwarz with
      // B' = bins + 2; its standard deviation is ~ sqrt(1/N) = 0.003, so 2 E-bound (0.046) is
      // > 7 sd above the mean. 2 N KL is the G statistic, ~ chi2 with <= B'-1 = 51 dof
      // (mean 51, sd 10): P(2 N KL > 130) < 1e-8.
      CHECK(l1_distance(h, ref) < 2.0 * std::sqrt((bins + 2.0) / n_samples));
      CHECK(2.0 * n_samples * kl_divergence(h, ref) < 130.0);
    }
  }
}

TEST_CASE("Wrong distributions fail: uniform in a cube, MB of another dimension", "[analysis]") {
  for (int d = 1; d <= 6; ++d) {
    INFO("D = " << d);
    // Uniform in [-sqrt3, sqrt3]^D has the MB variance kT/m = 1 per component, and the
    // parameter-free reference takes kT from the sample, as the recorder does.
    test::OwnedState st(d, n_samples);
    Rng rng(12, d);
    for (std::size_t i = 0; i < st.size(); ++i)
      for (int k = 0; k < d; ++k) st.velocity(i)[k] = std::sqrt(3.0) * (2.0 * rng.uniform() - 1.0);
    const Snapshot s = st.snapshot();
    for (Quantity q : {Quantity::speed, Quantity::component, Quantity::energy}) {
      INFO(to_string(q));
      const MaxwellReference ref = reference(s, q);
      CHECK(ref.kT == Approx(1.0).epsilon(0.01));
      const std::vector<double> x = values(s, q);
      const Histogram h = make_histogram(x, ref, bins);
      INFO("KS p " << ks_test(x, ref).p_value << " chi2 p " << chi_square_test(h, ref, 1).p_value
                   << " L1 " << l1_distance(h, ref));
      CHECK(ks_test(x, ref).p_value < 1e-10);
      CHECK(chi_square_test(h, ref, 1).p_value < 1e-10);
      CHECK(l1_distance(h, ref) > 2.0 * std::sqrt((bins + 2.0) / n_samples));
    }
    // True MB speeds of dimension d + 1 tested as if they were of dimension d.
    test::OwnedState other(d + 1, n_samples);
    test::fill_maxwell(other, rng, 1.0);
    std::vector<double> speeds;
    for (std::size_t i = 0; i < other.size(); ++i) {
      double vv = 0;
      for (int k = 0; k <= d; ++k) vv += other.velocity(i)[k] * other.velocity(i)[k];
      speeds.push_back(std::sqrt(vv));
    }
    // kT from the energy as a D-dimensional gas would compute it: <v^2> / d.
    double vv_mean = 0;
    for (double v : speeds) vv_mean += v * v;
    const MaxwellReference wrong{Quantity::speed, d, vv_mean / (d * double(n_samples)), 1.0};
    CHECK(ks_test(speeds, wrong).p_value < 1e-10);
    CHECK(chi_square_test(make_histogram(speeds, wrong, bins), wrong, 1).p_value < 1e-10);
  }
}

TEST_CASE("Mixtures: pooled mass-weighted speeds are MB only at one temperature", "[analysis]") {
  // Species 0 (mass 1) and 1 (mass 4), half each, D = 3.
  test::OwnedState st(3, n_samples);
  st.species.resize(n_samples);
  st.species_inv_mass = {1.0, 0.25};
  for (std::size_t i = 0; i < n_samples; ++i) st.species[i] = i % 2;
  Rng rng(13);
  auto fill = [&](double kT0, double kT1) {
    for (std::size_t i = 0; i < n_samples; ++i)
      for (int k = 0; k < 3; ++k)
        st.velocity(i)[k] = std::sqrt((i % 2 ? kT1 * 0.25 : kT0) * 1.0) * rng.normal();
  };
  fill(1.0, 1.0);
  Snapshot s = st.snapshot();
  CHECK(mean_mass(s) == Approx(2.5).epsilon(1e-15));
  CHECK(mean_mass(s, 1) == Approx(4.0).epsilon(1e-15));
  CHECK(count(s, 0) == n_samples / 2);
  // kT estimate: relative sd sqrt(2 / (3 N_s)) = 0.0037 for N_s = 5e4; 5 sd = 0.018.
  CHECK(temperature(s, 0) == Approx(1.0).epsilon(0.018));
  CHECK(temperature(s, 1) == Approx(1.0).epsilon(0.018));
  for (int sp : {-1, 1}) {
    const MaxwellReference ref = reference(s, Quantity::speed, sp);
    CHECK(ks_test(values(s, Quantity::speed, sp), ref).p_value > 1e-4);
    CHECK(chi_square_test(make_histogram(values(s, Quantity::speed, sp), ref), ref, 1).p_value >
          1e-4);
  }
  // Two temperatures (0.5 and 1.5, mean 1): each species is MB, the pooled gas is not.
  fill(0.5, 1.5);
  s = st.snapshot();
  const MaxwellReference ref = reference(s, Quantity::speed);
  CHECK(ks_test(values(s, Quantity::speed), ref).p_value < 1e-10);
  CHECK(chi_square_test(make_histogram(values(s, Quantity::speed), ref), ref, 1).p_value < 1e-10);
}

TEST_CASE("Kolmogorov tail and chi-square bookkeeping", "[analysis]") {
  // Q(lambda) at published points (Smirnov 1948 table): Q(1.36) = 0.0494, Q(1.63) = 0.0098.
  CHECK(kolmogorov_q(1.3581) == Approx(0.05).margin(2e-4));
  CHECK(kolmogorov_q(1.6276) == Approx(0.01).margin(1e-4));
  CHECK(kolmogorov_q(0.0) == 1.0);
  // A histogram that holds exactly the expected counts has chi2 = 0 (up to the merging of
  // the tail groups) and L1 = 0 when the counts equal N P_i.
  const MaxwellReference ref{Quantity::component, 1, 1.0, 1.0};
  Histogram h(-1.0, 1.0, 2);
  CHECK_THROWS_AS(chi_square_test(h, ref), InvalidInput);  // empty
  CHECK_THROWS_AS(h.add(NAN), InvalidInput);
  h.add(-3.0);
  h.add(0.5);
  h.add(5.0);
  CHECK(h.underflow() == 1.0);
  CHECK(h.overflow() == 1.0);
  CHECK(h.count(1) == 1.0);
  CHECK(h.total() == 3.0);
  CHECK(h.density(1) == Approx(1.0 / 3.0));
}

// ks_test orders large samples by a counting sort on an interpolated CDF and evaluates the
// exact CDF only where the maximum can be; its statistic must equal, bit for bit, that of
// sorting the sample and evaluating the exact CDF at every point (the definition).
TEST_CASE("ks_test equals the sort-and-evaluate definition bit for bit", "[analysis]") {
  const auto definition = [](std::vector<double> x, const MaxwellReference& ref) {
    std::sort(x.begin(), x.end());
    const double n = static_cast<double>(x.size());
    double d = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double f = ref.cdf(x[i]);
      d = std::max({d, (i + 1) / n - f, f - i / n});
    }
    return d;
  };
  for (int d : {1, 3, 6}) {
    test::OwnedState st(d, 50000);
    Rng rng(21, d);
    test::fill_maxwell(st, rng, 1.0);
    const Snapshot s = st.snapshot();
    for (Quantity q : {Quantity::speed, Quantity::component, Quantity::energy}) {
      const MaxwellReference ref{q, d, 1.0, 1.0};
      std::vector<double> x = values(s, q);
      INFO("D = " << d << ", " << to_string(q));
      CHECK(ks_test(x, ref).statistic == definition(x, ref));
      // the wrong temperature: the maximum sits elsewhere, many values share buckets
      const MaxwellReference hot{q, d, 1.7, 1.0};
      CHECK(ks_test(x, hot).statistic == definition(x, hot));
      // a concentrated sample (every value in a few buckets) and repeated values
      for (double& v : x) v = 1.0 + 1e-3 * std::round(v * 10.0);
      CHECK(ks_test(x, ref).statistic == definition(x, ref));
    }
  }
}
