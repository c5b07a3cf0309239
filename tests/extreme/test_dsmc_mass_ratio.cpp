// Mass ratios 1e6 and 1e-6 in a two-species DSMC gas: no NaN or infinity, momentum and
// energy conserved to round-off, and the cold heavy species is heated by the light one at
// the Landau-Teller exchange rate derived below.
//
// Exchange rate. A collision of particles 1, 2 (masses m1, m2, M = m1 + m2, mu = m1 m2 / M)
// keeps V = (m1 v1 + m2 v2)/M and |g|, g = v1 - v2, so exactly E1' - E1 = mu V.(g' - g).
// Averaged over the scattering law, E[g' | g] = (1 - kappa) g with kappa = 1 for isotropic
// scattering (Maxwell, VHS) and kappa = 4/(D + 1) for hard spheres (the normal has density
// ~ cos theta on the hemisphere, E[cos^2 theta] = 2/(D + 1); kappa = 1 in 3D, 2 in 1D).
// For Maxwellian species at T1, T2, g ~ N(0, s2 I), s2 = T1/m1 + T2/m2, and
// E[V | g] = (T1 - T2) g / (M s2). A cross pair collides at rate c |g|^a / (N - 1), so
//   dT1/dt = -lambda1 (T1 - T2),  lambda1 = 2 kappa mu c N2 E|g|^(2+a) / (D (N-1) M s2),
// E|g|^(2+a) = (2 s2)^(1+a/2) Gamma((D+2+a)/2) / Gamma(D/2); lambda2 likewise with N1, and
// T1 - T2 decays at lambda1 + lambda2 (the Landau-Teller form dT/dt = (T_eq - T)/tau; the
// classic light-heavy limit is tau^-1 ~ 2 (m_light/m_heavy) x collision frequency, cf.
// Landau & Lifshitz, Physical Kinetics, section 42). For Maxwell molecules (a = 0, c = 1)
// the law is exact for any distributions, lambda1 + lambda2 = 2 mu N / (M (N - 1)). For hard
// spheres it needs Maxwellian species: here the heavy species starts at T_h = 1e-6 T_l, so
// its own shape enters only at O(T_h / T_l) < 1e-3, and the light one stays Maxwellian.
// With constant rates (s2 changes by < 1e-4 in the run) the exact solution is
//   T_h(t) = T_h0 + lambda_h / (lambda_h + lambda_l) (T_l0 - T_h0) (1 - exp(-(lambda_h + lambda_l) t)).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "extreme/extreme_common.hpp"
#include "hypergas/dsmc/engine.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;

namespace {

constexpr Features kSpecies{.species = true};

/// Runs R replicas with the heavy species cold and checks the heating of the heavy species
/// against the theory above. `ratio` = m1/m0 (species 1 heavy for ratio > 1).
template <int D, class Model>
void check_exchange(double ratio) {
  const int R = 16;
  const std::size_t N = 4000;
  const double t_end = 40.0;
  const int heavy = ratio > 1.0 ? 1 : 0, light = 1 - heavy;
  Config cfg;
  cfg.n = N;
  cfg.init = InitialState::two_temp;
  cfg.initial.mass_ratio = ratio;
  cfg.initial.fraction = 0.5;
  cfg.initial.kT_species[heavy] = 1e-6;
  cfg.initial.kT_species[light] = 1.0;
  std::vector<double> rise(R), predicted(R);
  std::vector<int> ok(R, 0);
  extreme::for_replicas(R, [&](int r) {
    Config c = cfg;
    c.seed = 4242 + 97 * D + r + (ratio > 1.0 ? 0 : 1000);
    Engine<D, Model, kSpecies> e(c);
    const auto& p = e.particles();
    const double Th0 = extreme::species_temperature<D>(p, heavy);
    const double Tl0 = extreme::species_temperature<D>(p, light);
    const double mh = 1.0 / p.species_inv_mass(heavy), ml = 1.0 / p.species_inv_mass(light);
    const double M = mh + ml, mu = mh * ml / M, a = e.model().exponent();
    const double kappa = std::is_same_v<Model, HardSpheres> ? 4.0 / (D + 1.0) : 1.0;
    const double s2 = Th0 / mh + Tl0 / ml;
    const double g2a = std::pow(2.0 * s2, 1.0 + 0.5 * a) *
                       std::exp(std::lgamma(0.5 * (D + 2.0 + a)) - std::lgamma(0.5 * D));
    const double nh = 0.5 * N, nl = 0.5 * N;  // fraction 0.5
    const double base = 2.0 * kappa * mu * e.rate_constant() * g2a / (D * (N - 1.0) * M * s2);
    const double lh = base * nl, ll = base * nh, lt = lh + ll;
    predicted[r] = lh / lt * (Tl0 - Th0) * -std::expm1(-lt * t_end);
    const auto c0 = conserved(p);
    e.run_until(t_end);
    const auto [de, dp] = extreme::drifts<D>(c0, conserved(p));
    rise[r] = extreme::species_temperature<D>(p, heavy) - Th0;
    ok[r] = extreme::all_finite(p) && de < 1e-12 && dp < 1e-12 && e.collisions() > 0;
  });
  for (int r = 0; r < R; ++r) REQUIRE(ok[r]);
  // Student t test of the replica mean of the rise against the prediction, false-failure
  // probability 1e-4 per case (24 cases: 2.4e-3 in all). The prediction varies by < 1e-3
  // between replicas (their sampled Tl0), so its mean is used. Power: the rise is resolved
  // to better than 3 % (about 1 % expected: ~4e4 heavy-light collisions per replica).
  const auto [m, se] = extreme::mean_se(rise);
  const auto [pm, pse] = extreme::mean_se(predicted);
  INFO("D = " << D << ", mass ratio " << ratio << ": heavy T rise " << m << " +- " << se
              << ", Landau-Teller theory " << pm);
  REQUIRE(std::abs(m - pm) < extreme::t_threshold(1e-4, R) * se + 3.0 * pse);
  REQUIRE(se < 0.03 * pm);
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("DSMC hard spheres, mass ratio 1e6 and 1e-6: Landau-Teller heating",
                       "[dsmc][extreme]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  check_exchange<D, HardSpheres>(1e6);
  check_exchange<D, HardSpheres>(1e-6);
}

TEMPLATE_TEST_CASE_SIG("DSMC Maxwell molecules, mass ratio 1e6 and 1e-6: exact exchange law",
                       "[dsmc][extreme]", ((int D), D), 2, 3, 6) {
  check_exchange<D, MaxwellMolecules>(1e6);
  check_exchange<D, MaxwellMolecules>(1e-6);
}
