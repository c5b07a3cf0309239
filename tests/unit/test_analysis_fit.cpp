// Relaxation-time fit (analysis/fit.hpp) on synthetic data y = A exp(-k t) + c + noise.
//
// One fit must recover k within 4 reported standard errors (false failure 6e-5 if the error
// is right); over 300 replicas the pulls (k_fit - k) / error must have sd 1 within 0.2 (the
// sd of a sample sd of 300 values is 0.041, so 0.2 is ~5 sd; nonlinearity biases at the
// percent level for this signal-to-noise).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hypergas/analysis/fit.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/error.hpp"
#include "hypergas/rng.hpp"

using namespace hypergas;
using namespace hypergas::analysis;

namespace {
struct Synthetic {
  std::vector<double> t, y, sigma;
};
Synthetic make(Rng& rng, double a, double k, double c, double noise, std::size_t n = 60) {
  Synthetic s;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 0.1 * static_cast<double>(i);
    s.t.push_back(t);
    s.y.push_back(a * std::exp(-k * t) + c + noise * rng.normal());
    s.sigma.push_back(noise);
  }
  return s;
}
}  // namespace

TEST_CASE("Relaxation fit: exact data give the exact parameters", "[analysis]") {
  Rng rng(1);
  const Synthetic s = make(rng, 2.0, 0.7, 0.3, 0.0);
  const RelaxationFit f = fit_relaxation(s.t, s.y);
  CHECK(f.rate.value == Approx(0.7).epsilon(1e-8));
  CHECK(f.amplitude.value == Approx(2.0).epsilon(1e-8));
  CHECK(f.offset.value == Approx(0.3).epsilon(1e-8));
  CHECK(f.tau.value == Approx(1 / 0.7).epsilon(1e-8));
  const RelaxationFit g = fit_relaxation(s.t, s.y, {}, false, 0.3);
  CHECK(g.rate.value == Approx(0.7).epsilon(1e-8));
  CHECK(g.offset.error == 0.0);
}

TEST_CASE("Relaxation fit: noisy data give the rate within the reported error", "[analysis]") {
  Rng rng(31);
  const Synthetic s = make(rng, 1.0, 0.5, 0.1, 0.01);
  for (bool weighted : {true, false}) {
    const RelaxationFit f = fit_relaxation(s.t, s.y, weighted ? s.sigma : std::vector<double>{});
    INFO("weighted " << weighted << " rate " << f.rate.value << " +- " << f.rate.error);
    CHECK(std::abs(f.rate.value - 0.5) < 4 * f.rate.error);
    CHECK(f.rate.error < 0.05);  // informative: < 10% of the rate at this noise level
    CHECK(f.dof == 57);
  }
  double pull2 = 0;
  constexpr int replicas = 300;
  for (int r = 0; r < replicas; ++r) {
    const Synthetic x = make(rng, 1.0, 0.5, 0.1, 0.01);
    const RelaxationFit f = fit_relaxation(x.t, x.y, x.sigma);
    pull2 += std::pow((f.rate.value - 0.5) / f.rate.error, 2);
  }
  CHECK(std::sqrt(pull2 / replicas) == Approx(1.0).margin(0.2));
}

TEST_CASE("Relaxation fit rejects bad input", "[analysis]") {
  CHECK_THROWS_AS(fit_relaxation({0, 1, 2}, {1, 2}), InvalidInput);
  CHECK_THROWS_AS(fit_relaxation({0, 1, 2}, {1, 0.5, 0.2}), InvalidInput);  // too few points
  CHECK_THROWS_AS(fit_relaxation({0, 1, 2, 3}, {1, NAN, 0.2, 0.1}), InvalidInput);
  CHECK_THROWS_AS(fit_relaxation({0, 1, 2, 3}, {1, 0.5, 0.2, 0.1}, {1, 1, 0, 1}), InvalidInput);
  // Flat data determine no rate: the fit fails, or reports an error larger than the rate.
  for (const std::vector<double>& y :
       {std::vector<double>{1, 1, 1, 1, 1, 1}, std::vector<double>{1, 1.01, 0.99, 1, 1.02, 0.98}}) {
    try {
      const RelaxationFit f = fit_relaxation({0, 1, 2, 3, 4, 5}, y);
      CHECK(f.rate.error > std::abs(f.rate.value));
    } catch (const InvalidInput&) {
      SUCCEED("the fit reported its failure");
    }
  }
}

TEST_CASE("MomentsRecorder + fit: a relaxation with a known rate", "[analysis]") {
  // A model relaxation, D = 3: every particle starts uniform in a cube (variance 1 per
  // component, m4_ratio = (3 * 1.8 + 6) / 15 = 0.76); after step k the first
  // n - round(n (1-p)^k) particles have been replaced by MB draws at kT = 1. So
  // m4_ratio(t) = 1 - 0.24 exp(-lambda t) in expectation, lambda = -ln(1-p) / dt. The
  // sampling noise of the moments is correlated in time (the same particles), so the fit's
  // error understates it (1.5% reported); over 20 other seeds lambda_fit / lambda - 1 had
  // mean -0.008 and sd 0.025. The tolerance 15% is 6 sd (false failure < 1e-8 if normal);
  // it catches a wrong time unit or a wrong column, not small biases.
  constexpr std::size_t n = 100000;
  const double p = 0.1, dt = 0.5, lambda = -std::log(1 - p) / dt;
  std::vector<double> v(n * 3);
  Rng rng(61);
  for (double& x : v) x = std::sqrt(3.0) * (2 * rng.uniform() - 1);
  MomentsRecorder rec;
  std::size_t replaced = 0;
  for (int k = 0; k <= 40; ++k) {
    const auto target = n - static_cast<std::size_t>(std::llround(n * std::pow(1 - p, k)));
    for (; replaced < target; ++replaced)
      for (int c = 0; c < 3; ++c) v[3 * replaced + c] = rng.normal();
    Snapshot s;
    s.dim = 3;
    s.n = n;
    s.stride = 3;
    s.velocities = v.data();
    s.time = k * dt;
    rec.observe(s);
  }
  const RelaxationFit f = fit_relaxation(rec.column("time"), rec.column("m4_ratio"),
                                         rec.column("m4_ratio_err"), false, 1.0);
  INFO("lambda " << lambda << " fit " << f.rate.value << " +- " << f.rate.error << " amplitude "
                 << f.amplitude.value);
  CHECK(f.rate.value == Approx(lambda).epsilon(0.15));
  CHECK(f.amplitude.value == Approx(-0.24).epsilon(0.15));
  // The distances fall as the gas relaxes: the start fails KS, the end is near MB.
  CHECK(rec.column("ks_p_speed").front() < 1e-10);
  CHECK(rec.column("l1_speed").back() < 0.2 * rec.column("l1_speed").front());
}
