// Temperature ratio 1e6 in DSMC: two particles at 1e6 times the temperature of the others.
//
// The global majorant of dsmc::Engine (G = 2 max|v|) then rejects almost every candidate
// while the two hot particles cascade their energy into the gas. Checked: the engine stays
// finite and conserves energy and momentum to round-off (1e-12) through the cascade, the
// kurtosis is far from Maxwellian during it (t = 0.05), and the gas ends Maxwellian at the
// mixed temperature: <|v|^4> / <|v|^2>^2 = (D + 2)/D (Maxwell-Boltzmann in D dims,
// <v^4> = D (D+2) (kT/m)^2), tested with a Student t test over R = 16 replicas at
// false-failure probability 1e-4 per dimension (3e-4 in all); the tolerance is
// t_{1e-4, 15} standard errors of the replica mean, and the mean's standard error must be
// below 0.01 (the sample is large enough to resolve the Maxwellian value).
// N = 2 and speeds of 1e-150 and 1e150 keep both speeds (zero momentum) and conserve energy.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "extreme/extreme_common.hpp"
#include "hypergas/dsmc/engine.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;

namespace {

/// <|v|^4> / <|v|^2>^2 of a particle set (squares formed after normalising by <|v|^2>).
template <int D, Features F>
double kurtosis(const Particles<D, F>& p) {
  double m2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) m2 += p.velocity(i).squaredNorm();
  m2 /= p.size();
  double m4 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.velocity(i).squaredNorm() / m2;
    m4 += x * x;
  }
  return m4 / p.size();
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("DSMC temperature ratio 1e6: stiff majorant", "[dsmc][extreme]",
                       ((int D), D), 2, 3, 6) {
  const int R = 16;
  const std::size_t N = 20000;
  Config cfg;
  cfg.n = N;
  cfg.init = InitialState::two_temp;
  cfg.initial.fraction = 2.0 / N;  // the last two particles are hot
  cfg.initial.kT_species = {1.0, 1e6};
  std::vector<double> k_early(R), k_end(R);
  std::vector<int> ok(R, 0);
  extreme::for_replicas(R, [&](int r) {
    Config c = cfg;
    c.seed = 5000 + 17 * D + r;
    Engine<D, HardSpheres> e(c);
    const auto c0 = conserved(e.particles());
    e.run_until(0.05);
    k_early[r] = kurtosis(e.particles());
    e.run_until(20.0);
    k_end[r] = kurtosis(e.particles());
    const auto [de, dp] = extreme::drifts<D>(c0, conserved(e.particles()));
    ok[r] = extreme::all_finite(e.particles()) && de < 1e-12 && dp < 1e-12;
  });
  for (int r = 0; r < R; ++r) REQUIRE(ok[r]);
  const auto [m0, se0] = extreme::mean_se(k_early);
  const auto [m, se] = extreme::mean_se(k_end);
  INFO("D = " << D << ": kurtosis at t = 0.05 " << m0 << " +- " << se0 << ", final " << m
              << " +- " << se << ", Maxwell " << (D + 2.0) / D);
  // Two particles hold half the energy at the start: the kurtosis is ~N/4 then, and still
  // far above Maxwell during the cascade.
  REQUIRE(m0 > 2.0 * (D + 2.0) / D);
  REQUIRE(std::abs(m - (D + 2.0) / D) < extreme::t_threshold(1e-4, R) * se);
  REQUIRE(se < 0.01);
}

TEST_CASE("DSMC: N = 2, tiny and huge velocity scales", "[dsmc][extreme]") {
  // N = 2 keeps both speeds (zero momentum); scales 1e-150 and 1e150 conserve energy and
  // momentum to round-off in a gas of 5000.
  for (double s : {1e-150, 1.0, 1e150}) {
    Config cfg;
    cfg.n = 2;
    cfg.init = InitialState::maxwell;
    cfg.initial.kT = s * s;
    Engine<4, HardSpheres> e(cfg);
    const double v0 = e.particles().velocity(0).norm();
    e.run_until(1000.0);
    REQUIRE(e.collisions() > 100);
    REQUIRE(std::abs(e.particles().velocity(0).norm() - v0) < 1e-12 * v0);
    cfg.n = 5000;
    Engine<6, HardSpheres> f(cfg);
    const auto c0 = conserved(f.particles());
    f.run_until(2.0);
    const auto [de, dp] = extreme::drifts<6>(c0, conserved(f.particles()));
    REQUIRE(extreme::all_finite(f.particles()));
    REQUIRE(de < 1e-12);
    REQUIRE(dp < 1e-12);
  }
}
