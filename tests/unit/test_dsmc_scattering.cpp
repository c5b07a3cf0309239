// Unit tests of the DSMC pieces: scattering laws, models, time unit, Maxwell-molecule theory.
// Statistical checks use fixed seeds; each states its false-failure probability.
#include <catch2/catch.hpp>

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "support/statistics.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/dsmc/maxwell_theory.hpp"
#include "hypergas/dsmc/models.hpp"
#include "hypergas/dsmc/time_unit.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;

using test_support::ks_pvalue;

namespace {
constexpr int n_samples = 100000;
}  // namespace

TEMPLATE_TEST_CASE_SIG("isotropic directions: unit, zero mean, covariance I/D", "[dsmc]",
                       ((int D), D), 1, 2, 3, 4, 5, 6) {
  // Mean components have sd 1/sqrt(D N), diagonal second moments sd
  // sqrt((3/(D(D+2)) - 1/D^2)/N); |z| < 5 per entry, <= 12 entries: false failure < 1e-5.
  Rng rng(17, D);
  Vec<D> mean = Vec<D>::Zero(), diag = Vec<D>::Zero();
  for (int s = 0; s < n_samples; ++s) {
    const Vec<D> u = isotropic_direction<D>(rng);
    REQUIRE(std::abs(u.squaredNorm() - 1.0) < 1e-15 * D);
    mean += u;
    diag += u.cwiseProduct(u);
  }
  mean /= n_samples;
  diag /= n_samples;
  const double sd_mean = std::sqrt(1.0 / (D * double(n_samples)));
  const double sd_diag =
      std::sqrt(std::max(3.0 / (D * (D + 2.0)) - 1.0 / (D * D), 1e-30) / n_samples);
  for (int k = 0; k < D; ++k) {
    REQUIRE(std::abs(mean[k]) < 5 * sd_mean);
    if (D > 1) REQUIRE(std::abs(diag[k] - 1.0 / D) < 5 * sd_diag);
  }
}

TEMPLATE_TEST_CASE_SIG("isotropic directions: joint fourth moments of pairs of components",
                       "[dsmc]", ((int D), D), 2, 3, 4, 5, 6) {
  // The marginal tests below cannot see how the samplers join their parts (two disks in
  // D = 4, a median and S^3 in D = 5, three planar pairs in D = 6). For sigma uniform on
  // S^(D-1), E[sigma_k^2 sigma_l^2] = 1/(D(D+2)) for every k != l, and E[sigma_k^4
  // sigma_l^4] = 9/(D(D+2)(D+4)(D+6)) gives the sample mean's sd. Every pair k < l is
  // checked (at most 15) at |z| < 5: false failure < 1e-5 per D.
  Rng rng(43, D);
  Eigen::Matrix<double, D, D> m = Eigen::Matrix<double, D, D>::Zero();
  for (int s = 0; s < n_samples; ++s) {
    const Vec<D> u = isotropic_direction<D>(rng);
    const Vec<D> u2 = u.cwiseProduct(u);
    m += u2 * u2.transpose();
  }
  m /= n_samples;
  const double expect = 1.0 / (D * (D + 2.0));
  const double var = 9.0 / (D * (D + 2.0) * (D + 4.0) * (D + 6.0)) - expect * expect;
  const double sd = std::sqrt(var / n_samples);
  for (int k = 0; k < D; ++k)
    for (int l = k + 1; l < D; ++l) {
      INFO("D = " << D << ", components " << k << ", " << l << ": " << m(k, l));
      REQUIRE(std::abs(m(k, l) - expect) < 5 * sd);
    }
}

TEMPLATE_TEST_CASE_SIG("isotropic directions: component law Beta(1/2, (D-1)/2)", "[dsmc]",
                       ((int D), D), 2, 3, 4, 5, 6) {
  // For sigma uniform on S^(D-1), sigma_k^2 ~ Beta(1/2, (D-1)/2) for every k. The first and
  // last components come from different parts of the samplers (ball / circle); KS p-value
  // > 1e-4 for each: false failure < 2e-4 per D.
  Rng rng(31, D);
  std::vector<double> first, last;
  for (int s = 0; s < n_samples; ++s) {
    const Vec<D> u = isotropic_direction<D>(rng);
    first.push_back(u[0] * u[0]);
    last.push_back(u[D - 1] * u[D - 1]);
  }
  auto cdf = [](double x) { return gsl_cdf_beta_P(std::clamp(x, 0.0, 1.0), 0.5, 0.5 * (D - 1)); };
  REQUIRE(ks_pvalue(first, cdf) > 1e-4);
  REQUIRE(ks_pvalue(last, cdf) > 1e-4);
}

TEMPLATE_TEST_CASE_SIG("hard-sphere deflection: |g| kept, deflection angle law", "[dsmc]",
                       ((int D), D), 2, 3, 4, 5, 6) {
  // With t = g_hat . n, cos chi = g_hat . g'_hat = 1 - 2 t^2 = 2 s - 1 and s = 1 - t^2 is
  // Beta((D-1)/2, 1): P(s <= x) = x^((D-1)/2). KS p-value > 1e-4 (false failure 1e-4 per D).
  // The component of g' orthogonal to g has zero mean (|z| < 5 per component).
  Rng rng(23, D);
  Vec<D> g;
  for (int k = 0; k < D; ++k) g[k] = 0.3 * (k + 1) * ((k % 2) ? -1.0 : 1.0);
  const double gn = g.norm();
  const Vec<D> gh = g / gn;
  std::vector<double> s;
  Vec<D> perp = Vec<D>::Zero();
  for (int i = 0; i < n_samples; ++i) {
    const Vec<D> gp = HardSpheres::deflect<D>(g, gn, rng);
    REQUIRE(std::abs(gp.norm() - gn) < 1e-14 * gn);
    const double c = gp.dot(gh) / gn;
    s.push_back(0.5 * (1.0 + c));
    perp += gp / gn - c * gh;
  }
  const double p =
      ks_pvalue(s, [](double x) { return std::pow(std::clamp(x, 0.0, 1.0), 0.5 * (D - 1)); });
  REQUIRE(p > 1e-4);
  perp /= n_samples;
  for (int k = 0; k < D; ++k) REQUIRE(std::abs(perp[k]) < 5.0 / std::sqrt(double(n_samples)));
}

TEST_CASE("hard-sphere deflection in 1D reverses g; g along the last axis is stable", "[dsmc]") {
  Rng rng(1);
  REQUIRE(HardSpheres::deflect<1>(Vec<1>(2.5), 2.5, rng)[0] == -2.5);
  // g exactly along +-e_L exercises both Householder signs.
  for (double sgn : {1.0, -1.0}) {
    Vec<4> g = Vec<4>::Zero();
    g[3] = sgn * 2.0;
    for (int i = 0; i < 1000; ++i) {
      const Vec<4> gp = HardSpheres::deflect<4>(g, 2.0, rng);
      REQUIRE(gp.allFinite());
      REQUIRE(std::abs(gp.norm() - 2.0) < 1e-14);
    }
  }
}

TEST_CASE("models: names, exponents, acceptance rules", "[dsmc]") {
  REQUIRE(registry::model("hs").index == 0);
  REQUIRE(registry::model("maxwell").index == 1);
  REQUIRE(registry::model("vhs").index == 2);
  REQUIRE_THROWS_AS(registry::model("HS"), InvalidInput);
  REQUIRE(VariableHardSpheres::name == "vhs");
  REQUIRE_THROWS_AS(VariableHardSpheres(1.5), InvalidInput);
  REQUIRE_THROWS_AS(VariableHardSpheres(-0.1), InvalidInput);
  static_assert(!MaxwellMolecules::needs_majorant && HardSpheres::needs_majorant);
  // Acceptance probability (|g|/G)^a: at g2 = G^2/4, HS accepts u < 1/2, VHS(0.5) u < 1/sqrt2.
  REQUIRE(HardSpheres::accept(1.0, 0.49, 2.0));
  REQUIRE_FALSE(HardSpheres::accept(1.0, 0.51, 2.0));
  const VariableHardSpheres v(0.5);
  REQUIRE(v.accept(1.0, 0.70, 2.0));
  REQUIRE_FALSE(v.accept(1.0, 0.71, 2.0));
}

TEST_CASE("time unit: <|g|^a> of a Maxwellian pair", "[dsmc]") {
  // 3D, m = kT = 1: <|g|> = 4/sqrt(pi) (e.g. Chapman & Cowling), <|g|^2> = 2 D kT/m.
  REQUIRE(mean_relative_speed_power(3, 1.0, 2.0) ==
          Approx(4.0 / std::sqrt(std::numbers::pi)).epsilon(1e-14));
  for (int d = 1; d <= 6; ++d) {
    REQUIRE(mean_relative_speed_power(d, 2.0, 2.0) == Approx(2.0 * d).epsilon(1e-13));
    REQUIRE(mean_relative_speed_power(d, 0.0, 7.0) == Approx(1.0).epsilon(1e-14));
  }
  // 2D: |g| Rayleigh with sigma^2 = 2: mean sigma sqrt(pi/2) = sqrt(pi).
  REQUIRE(mean_relative_speed_power(2, 1.0, 2.0) ==
          Approx(std::sqrt(std::numbers::pi)).epsilon(1e-14));
}

TEST_CASE("time unit: rate constant from the conserved energy, one and two species", "[dsmc]") {
  // Two particles with v = +-1 in 3D: sum m v^2 = 2 over D (N-1) = 3 dof: kT = 2/3.
  Particles<3> p(2);
  p.velocity(0) = Vec<3>(1, 0, 0);
  p.velocity(1) = Vec<3>(-1, 0, 0);
  REQUIRE(equilibrium_temperature(p) == Approx(2.0 / 3.0));
  REQUIRE(rate_constant(p, 1.0) == Approx(1.0 / mean_relative_speed_power(3, 1.0, 4.0 / 3.0)));
  // Species: 2 of mass 1 and 2 of mass 4, each pair class weighted by its exact fraction.
  Particles<2, Features{.species = true}> q(4);
  q.set_species_mass(1, 4.0);
  q.set_species(2, 1);
  q.set_species(3, 1);
  q.velocity(0) = Vec<2>(1, 0);
  q.velocity(1) = Vec<2>(-1, 0);
  q.velocity(2) = Vec<2>(0, 0.5);
  q.velocity(3) = Vec<2>(0, -0.5);
  const double kT = (1 + 1 + 4 * 0.25 * 2) / (2.0 * 3.0);
  REQUIRE(equilibrium_temperature(q) == Approx(kT));
  const double a = 1.0;
  const double mean = (2.0 / 12) * mean_relative_speed_power(2, a, 2 * kT) +
                      (2.0 / 12) * mean_relative_speed_power(2, a, 0.5 * kT) +
                      (8.0 / 12) * mean_relative_speed_power(2, a, 1.25 * kT);
  REQUIRE(rate_constant(q, a) == Approx(1.0 / mean).epsilon(1e-13));
  Particles<3> cold(5);
  REQUIRE_THROWS_AS(rate_constant(cold, 1.0), InvalidInput);
}

TEST_CASE("Maxwell-molecule theory: m4 rate and BKW moments", "[dsmc]") {
  REQUIRE(maxwell_m4_rate(1) == 0.0);
  REQUIRE(maxwell_m4_rate(3) == Approx(1.0 / 3.0));
  for (int d = 1; d <= 6; ++d) {
    // t = 0: the BKW initial state's m4 = D^2 (D+4)/(D+2); t -> inf: Maxwellian D (D+2).
    REQUIRE(bkw_m4(d, 0.0) == Approx(d * d * (d + 4.0) / (d + 2.0)).epsilon(1e-14));
    if (d > 1) REQUIRE(bkw_m4(d, 1e4) == Approx(d * (d + 2.0)).epsilon(1e-12));  // 1D: rate 0
    // m4 - m4_eq decays at the fourth-moment rate.
    const double r = (bkw_m4(d, 2.0) - d * (d + 2.0)) / (bkw_m4(d, 1.0) - d * (d + 2.0));
    if (d > 1) REQUIRE(r == Approx(std::exp(-maxwell_m4_rate(d))).epsilon(1e-12));
  }
  // The classical 3D result K = 1 - (2/5) exp(-t/6) (Krook & Wu 1976).
  REQUIRE(bkw_K(3, 6.0) == Approx(1.0 - 0.4 * std::exp(-1.0)).epsilon(1e-14));
}
