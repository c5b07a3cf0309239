// Velocity moments with standard errors (analysis/moments.hpp).
//
// Exact values on a hand-made snapshot; MB samples reproduce <v^2> = D kT/m,
// <v^4> = D(D+2)(kT/m)^2, <v^6> = D(D+2)(D+4)(kT/m)^3 and kurtosis 3 within 5 reported
// standard errors (two-sided normal p = 5.7e-7 per check, 30 checks: false-failure
// probability < 2e-5); the reported errors are honest: over 400 replicas the pulls
// (estimate - truth) / error have standard deviation 1 within 0.15 (the sd of a sample sd
// of 400 normal values is 1/sqrt(800) = 0.035, so 0.15 is > 4 sd; the delta-method
// kurtosis error has an O(1/n) bias, negligible at n = 2000).
#include <catch2/catch.hpp>

#include <cmath>

#include "hypergas/analysis/moments.hpp"
#include "hypergas/error.hpp"
#include "test_analysis_support.hpp"

using namespace hypergas;
using namespace hypergas::analysis;

TEST_CASE("Moments of a hand-made snapshot are exact", "[analysis]") {
  // D = 2, two particles (3, 4) and (0, 0): |v|^2 = 25 and 0.
  test::OwnedState st(2, 2);
  st.velocity(0)[0] = 3;
  st.velocity(0)[1] = 4;
  st.velocity(1)[0] = 0;
  st.velocity(1)[1] = 0;
  const Moments m = compute_moments(st.snapshot());
  CHECK(m.n == 2);
  CHECK(m.m2.value == 12.5);
  CHECK(m.m4.value == 312.5);
  CHECK(m.m6.value == 7812.5);
  CHECK(m.kT == 6.25);  // sum v^2 / (D n) = 25 / 4
  CHECK(m.kurtosis_x.value == Approx(81.0 / 2 / (4.5 * 4.5)));
  // Standard error of m2: sample sd of {25, 0} is 25/sqrt2, over sqrt(2).
  CHECK(m.m2.error == Approx(12.5));
  // Species selection: two species, species 1 heavy (mass 4).
  st.species = {0, 1};
  st.species_inv_mass = {1.0, 0.25};
  st.velocity(1)[0] = 1;
  CHECK_THROWS_AS(compute_moments(st.snapshot(), 1), InvalidInput);  // one particle only
  CHECK(compute_moments(st.snapshot()).kT == Approx((25.0 + 4.0 * 1.0) / 4.0));
}

TEST_CASE("MB samples: moments within their reported errors, and honest errors", "[analysis]") {
  constexpr std::size_t n = 200000;
  for (int d = 1; d <= 6; ++d) {
    INFO("D = " << d);
    test::OwnedState st(d, n);
    Rng rng(21, d);
    const double a = 0.8;  // kT/m
    test::fill_maxwell(st, rng, a);
    const Moments m = compute_moments(st.snapshot());
    CHECK(std::abs(m.m2.value - d * a) < 5 * m.m2.error);
    CHECK(std::abs(m.m4.value - d * (d + 2.0) * a * a) < 5 * m.m4.error);
    CHECK(std::abs(m.m6.value - d * (d + 2.0) * (d + 4.0) * a * a * a) < 5 * m.m6.error);
    CHECK(std::abs(m.kurtosis_x.value - 3.0) < 5 * m.kurtosis_x.error);
    CHECK(std::abs(m.m4_ratio.value - 1.0) < 5 * m.m4_ratio.error);
  }
  // Pull distributions over replicas, D = 3.
  constexpr int replicas = 400;
  constexpr std::size_t small = 2000;
  double p2 = 0, p4 = 0, pk = 0;
  Rng rng(22);
  for (int r = 0; r < replicas; ++r) {
    test::OwnedState st(3, small);
    test::fill_maxwell(st, rng, 1.0);
    const Moments m = compute_moments(st.snapshot());
    p2 += std::pow((m.m2.value - 3.0) / m.m2.error, 2);
    p4 += std::pow((m.m4.value - 15.0) / m.m4.error, 2);
    pk += std::pow((m.kurtosis_x.value - 3.0) / m.kurtosis_x.error, 2);
  }
  CHECK(std::sqrt(p2 / replicas) == Approx(1.0).margin(0.15));
  CHECK(std::sqrt(p4 / replicas) == Approx(1.0).margin(0.15));
  CHECK(std::sqrt(pk / replicas) == Approx(1.0).margin(0.15));
}

TEST_CASE("Microcanonical gas: m4_ratio is M/(M+2), not 1 (M = D N)", "[analysis]") {
  // Velocities uniform on the energy sphere |V|^2 = const in R^M (a normalised Gaussian
  // vector): with kT from the snapshot, E[<v^4>] / (D(D+2) kT^2) = M/(M+2) exactly (the
  // caveat in analysis/README.md). N = 10, D = 3: 30/32 = 0.9375. Checked to 5 standard
  // errors of the replica mean (false failure 5.7e-7); the difference from 1 is ~20 of them.
  constexpr int d = 3, n = 10, replicas = 20000;
  constexpr double m_dim = d * n;
  Rng rng(23);
  double sum = 0, sum_sq = 0;
  for (int r = 0; r < replicas; ++r) {
    test::OwnedState st(d, n);
    test::fill_maxwell(st, rng, 1.0);  // any scale: m4_ratio is scale-free
    const double x = compute_moments(st.snapshot()).m4_ratio.value;
    sum += x;
    sum_sq += x * x;
  }
  const double mean = sum / replicas;
  const double se = std::sqrt((sum_sq / replicas - mean * mean) / (replicas - 1));
  INFO("mean " << mean << " +- " << se);
  CHECK(std::abs(mean - m_dim / (m_dim + 2)) < 5 * se);
  CHECK(std::abs(mean - 1.0) > 10 * se);
}
