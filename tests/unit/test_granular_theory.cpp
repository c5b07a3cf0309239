// Tests of the granular-gas theory (include/hypergas/granular/theory.hpp): elastic limits,
// the published closed forms, the cooling rate against an independent deterministic
// quadrature of the energy-loss collision integral, the Sonine moment conventions, Haff's
// law and the Enskog collision frequency. Deterministic: no statistical tolerance.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "hypergas/granular/theory.hpp"

using namespace hypergas::granular;

namespace {
constexpr double pi = std::numbers::pi;

// Composite Simpson rule on [a, b] with n (even) intervals.
template <class F>
double simpson(F f, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

// zeta / nu_M(T) of a Maxwellian at T = 1 by quadrature, independent of the closed form.
// |g| = sqrt(2) x with x chi-distributed with D degrees of freedom (g has variance 2T per
// component); the normal n makes the angle theta in [0, pi/2] with g, with the weight
// cos(theta) sin(theta)^(D-2) (hard-sphere rate g.n times the measure on S^(D-1)).
// Per particle: collision rate kappa <|g|> = 1, energy change (kappa/2) <|g| dE>,
// dE = -(1 - alpha^2)(g.n)^2/4, and T = 2e/D, so zeta = -(1/D) <|g| dE>_n / <|g|>.
double zeta_quadrature(double alpha, int d) {
  const auto px = [d](double x) { return std::pow(x, d - 1) * std::exp(-0.5 * x * x); };
  const auto wt = [d](double th) { return std::cos(th) * std::pow(std::sin(th), d - 2); };
  const double norm_t = simpson(wt, 0.0, 0.5 * pi, 2000);
  const double cos2 =
      simpson([&](double th) { return wt(th) * std::cos(th) * std::cos(th); }, 0.0, 0.5 * pi,
              2000) /
      norm_t;
  const double g1 = simpson([&](double x) { return px(x) * std::sqrt(2.0) * x; }, 0.0, 16.0, 4000);
  const double g3 =
      simpson([&](double x) { return px(x) * std::pow(std::sqrt(2.0) * x, 3); }, 0.0, 16.0, 4000);
  const double de = -(1.0 - alpha * alpha) / 4.0 * cos2 * g3 / g1;  // <|g| dE>/<|g|>
  return -de / d;
}

// Moments <c^(2k)> of f = phi (1 + a2 S2(c^2) + a3 S3(c^2)) by quadrature over y = c^2
// (density y^(D/2-1) e^(-y) / Gamma(D/2)).
double sonine_moment(int k, int d, double a2, double a3) {
  const double h = 0.5 * d;
  const auto s2 = [d](double y) { return y * y / 2 - (d + 2.0) * y / 2 + d * (d + 2.0) / 8; };
  const auto s3 = [d](double y) {
    return -y * y * y / 6 + (d + 4.0) * y * y / 4 - (d + 2.0) * (d + 4.0) * y / 8 +
           d * (d + 2.0) * (d + 4.0) / 48;
  };
  // substitute y = u^2 so the integrand is smooth at 0 for every D
  return simpson(
      [&](double u) {
        const double y = u * u;
        return 2.0 * u * std::pow(y, h - 1.0 + k) * std::exp(-y) *
               (1.0 + a2 * s2(y) + a3 * s3(y)) / std::tgamma(h);
      },
      0.0, 8.0, 8000);
}
}  // namespace

TEST_CASE("granular theory: elastic limit", "[granular]") {
  CHECK(cooling_rate(1.0, 1, 0.0) == 0.0);
  CHECK_THROWS_AS(a2_hcs(0.5, 1), hypergas::InvalidInput);
  for (int d = 2; d <= 6; ++d) {
    CHECK(a2_hcs(1.0, d) == 0.0);
    CHECK(a2_white_noise(1.0, d) == 0.0);
    CHECK(cooling_rate(1.0, d, 0.0) == 0.0);
    const SecondSonine s = hcs_second_sonine(1.0, d);
    CHECK(std::abs(s.a2) < 1e-15);
    CHECK(std::abs(s.a3) < 1e-15);
    CHECK(hcs_band(1.0, d) < 1e-15);
  }
  CHECK_THROWS_AS(haff_t0(1.0, 3, 0.0), hypergas::InvalidInput);
  CHECK_THROWS_AS(a2_hcs(1.5, 3), hypergas::InvalidInput);
  CHECK_THROWS_AS(a2_hcs(-0.1, 3), hypergas::InvalidInput);
}

TEST_CASE("a2 of the HCS changes sign at alpha = 1/sqrt(2) in D = 2..6", "[granular]") {
  const double ac = 1.0 / std::sqrt(2.0);
  for (int d = 2; d <= 6; ++d) {
    CHECK(std::abs(a2_hcs(ac, d)) < 1e-15);
    CHECK(std::abs(a2_white_noise(ac, d)) < 1e-15);
    CHECK(a2_hcs(ac - 0.01, d) > 0.0);
    CHECK(a2_hcs(ac + 0.01, d) < 0.0);
    CHECK(a2_hcs(0.0, d) > 0.0);
    CHECK(a2_hcs(0.9, d) < 0.0);
    // the second Sonine value is close to the first for weak dissipation
    const double a1 = a2_hcs(0.95, d), a2 = hcs_second_sonine(0.95, d).a2;
    CHECK(std::abs(a2 - a1) < 0.1 * std::abs(a1));
  }
}

TEST_CASE("a2 agrees with the published closed forms", "[granular]") {
  using Catch::Matchers::WithinRel;
  // van Noije & Ernst, Granular Matter 1, 57 (1998), HCS:
  // 3D 16(1-a)(1-2a^2)/(81 - 17a + 30a^2(1-a)); 2D denominator 57 - 25a + 30a^2(1-a).
  // White noise, 3D: denominator 241 - 177a + 30a^2(1-a); 2D: 185 - 153a + 30a^2(1-a).
  for (double a = 0.0; a <= 1.0; a += 0.05) {
    const double num = 16.0 * (1 - a) * (1 - 2 * a * a), c = 30.0 * a * a * (1 - a);
    CHECK_THAT(a2_hcs(a, 3), WithinRel(num / (81 - 17 * a + c), 1e-14) ||
                                 Catch::Matchers::WithinAbs(0.0, 1e-16));
    CHECK_THAT(a2_hcs(a, 2), WithinRel(num / (57 - 25 * a + c), 1e-14) ||
                                 Catch::Matchers::WithinAbs(0.0, 1e-16));
    CHECK_THAT(a2_white_noise(a, 3), WithinRel(num / (241 - 177 * a + c), 1e-14) ||
                                         Catch::Matchers::WithinAbs(0.0, 1e-16));
    CHECK_THAT(a2_white_noise(a, 2), WithinRel(num / (185 - 153 * a + c), 1e-14) ||
                                         Catch::Matchers::WithinAbs(0.0, 1e-16));
  }
  // Exact values at alpha = 1/2: 3D 16/305 = 0.052459, 2D 16/193 = 0.082902;
  // white noise 3D 16/625 = 0.0256.
  CHECK_THAT(a2_hcs(0.5, 3), WithinRel(16.0 / 305.0, 1e-14));
  CHECK_THAT(a2_hcs(0.5, 2), WithinRel(16.0 / 193.0, 1e-14));
  CHECK_THAT(a2_white_noise(0.5, 3), WithinRel(16.0 / 625.0, 1e-14));
  // alpha = 0 (sticky limit): 3D 16/81, 2D 16/57.
  CHECK_THAT(a2_hcs(0.0, 3), WithinRel(16.0 / 81.0, 1e-14));
  CHECK_THAT(a2_hcs(0.0, 2), WithinRel(16.0 / 57.0, 1e-14));
}

TEST_CASE("second Sonine HCS values (derived in docs/validation.md)", "[granular]") {
  using Catch::Matchers::WithinAbs;
  // 3D, alpha = 0.5: a2 = 0.04499, a3 = -0.01768; 2D, alpha = 0.5: 0.06545, -0.03711.
  const SecondSonine s3 = hcs_second_sonine(0.5, 3), s2 = hcs_second_sonine(0.5, 2);
  CHECK_THAT(s3.a2, WithinAbs(0.04499, 5e-6));
  CHECK_THAT(s3.a3, WithinAbs(-0.01768, 5e-6));
  CHECK_THAT(s2.a2, WithinAbs(0.06545, 5e-6));
  CHECK_THAT(s2.a3, WithinAbs(-0.03711, 5e-6));
  CHECK_THAT(hcs_band(0.9, 3), WithinAbs(0.0022, 5e-5));
  CHECK_THAT(hcs_band(0.5, 3), WithinAbs(0.0149, 5e-5));
}

TEST_CASE("cooling rate of a Maxwellian against a quadrature, D = 2..6", "[granular]") {
  using Catch::Matchers::WithinRel;
  for (int d = 2; d <= 6; ++d)
    for (double a : {0.0, 0.3, 0.7, 0.9, 0.99}) {
      const double q = zeta_quadrature(a, d);
      CHECK_THAT(cooling_rate(a, d, 0.0), WithinRel(q, 1e-9));
      CHECK_THAT(cooling_rate(a, d, 0.0), WithinRel((1 - a * a) / d, 1e-15));
    }
  // the (D+2)/(4D) form in units of nu = p/eta_0 = 4/(D+2) nu_M, first Sonine
  for (int d = 2; d <= 6; ++d) {
    const double a = 0.8, a2 = a2_hcs(a, d);
    CHECK_THAT(cooling_rate(a, d, a2) / (4.0 / (d + 2.0)),
               WithinRel((d + 2.0) / (4.0 * d) * (1 - a * a) * (1 + 3 * a2 / 16), 1e-14));
  }
}

TEST_CASE("a2 and a3 from moments follow the Sonine convention", "[granular]") {
  using Catch::Matchers::WithinAbs;
  for (int d = 1; d <= 6; ++d)
    for (const auto& [a2, a3] : {std::pair{0.0, 0.0}, {0.05, -0.02}, {-0.03, 0.01}}) {
      // velocity moments at T = 1/2 (v_T = 1): <v^(2k)> = <c^(2k)>
      const double m2 = sonine_moment(1, d, a2, a3), m4 = sonine_moment(2, d, a2, a3),
                   m6 = sonine_moment(3, d, a2, a3);
      CHECK_THAT(m2, WithinAbs(0.5 * d, 1e-10));  // S2, S3 do not change T
      CHECK_THAT(a2_from_moments(m2, m4, d), WithinAbs(a2, 1e-10));
      CHECK_THAT(a3_from_moments(m2, m4, m6, d), WithinAbs(a3, 1e-10));
    }
  // a delta shell |v| = 1: a2 = -2/(D+2)
  for (int d = 1; d <= 6; ++d)
    CHECK_THAT(a2_from_moments(1.0, 1.0, d), WithinAbs(-2.0 / (d + 2.0), 1e-15));
}

TEST_CASE("Haff's law: t0 = 2/zeta solves dT/dt = -zeta sqrt(T/T0) T", "[granular]") {
  using Catch::Matchers::WithinRel;
  for (int d = 2; d <= 6; ++d) {
    const double a = 0.8, a2 = a2_hcs(a, d), z = cooling_rate(a, d, a2),
                 t0 = haff_t0(a, d, a2);
    CHECK_THAT(t0, WithinRel(2.0 / z, 1e-15));
    // RK4 of dT/dt = -z T^(3/2) from T = 1 to t = 5 t0
    const auto f = [z](double T) { return -z * T * std::sqrt(T); };
    double T = 1.0;
    const int n = 20000;
    const double h = 5.0 * t0 / n;
    for (int i = 0; i < n; ++i) {
      const double k1 = f(T), k2 = f(T + 0.5 * h * k1), k3 = f(T + 0.5 * h * k2),
                   k4 = f(T + h * k3);
      T += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    CHECK_THAT(T, WithinRel(haff_temperature_ratio(5.0 * t0, t0), 1e-10));
    CHECK_THAT(haff_temperature_ratio(5.0 * t0, t0), WithinRel(1.0 / 36.0, 1e-15));
  }
}

TEST_CASE("collision frequency ratio and Enskog collision frequency", "[granular]") {
  using Catch::Matchers::WithinRel;
  CHECK(collision_frequency_ratio(0.0) == 1.0);
  CHECK_THAT(collision_frequency_ratio(0.16), WithinRel(0.99, 1e-15));
  // 3D textbook (Chapman & Cowling): nu = 4 n sigma^2 chi sqrt(pi kT/m), n = 6 eta/pi.
  for (double eta : {0.01, 0.1, 0.2618, 0.4}) {
    const double chi = chi_carnahan_starling(eta);
    const double n = 6.0 * eta / pi;
    CHECK_THAT(enskog_collision_frequency(3, eta, chi),
               WithinRel(4.0 * n * chi * std::sqrt(pi), 1e-14));
  }
  // every D: Omega_D n chi with n = eta / v_D (the Boltzmann rate times chi)
  for (int d = 1; d <= 6; ++d) {
    const double omega = 2.0 * std::pow(pi, 0.5 * (d - 1)) / std::tgamma(0.5 * d);
    const double vd = std::pow(pi, 0.5 * d) / (std::tgamma(0.5 * d + 1.0) * std::pow(2.0, d));
    CHECK_THAT(enskog_collision_frequency(d, 0.1, 1.3), WithinRel(omega * 0.1 / vd * 1.3, 1e-13));
  }
  // contact values reproduce the equations of state of docs/validation.md's table
  CHECK_THAT(1.0 + 4.0 * 0.2618 * chi_carnahan_starling(0.2618), WithinRel(3.2625, 1e-4));
  CHECK_THAT(1.0 + 2.0 * 0.3 * chi_henderson(0.3), WithinRel(2.0638, 1e-4));
}
