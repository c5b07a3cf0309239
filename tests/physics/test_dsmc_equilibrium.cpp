// Hard spheres and VHS: the equilibrium collision rate equals its exact value (one collision
// per particle per unit time, dsmc/time_unit.hpp); every initial state relaxes to the
// D-dimensional Maxwell-Boltzmann law (speed^2 / (kT/m) chi-square with D degrees of
// freedom); a Maxwellian stays Maxwellian; 1D equal masses never relax, two masses do.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hypergas/registry.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "physics/test_dsmc_common.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;
using namespace dsmc_test;

namespace {
template <int D, class Model>
void check_rate(double a) {
  // From a Maxwellian, 40 blocks of 5 mean collision times: collisions per particle per
  // block should be 5 (2 * collisions / N per unit time = 1). Block means are independent to
  // a good approximation (correlation time ~1); t test with false-failure 1e-5 per case.
  Config cfg;
  cfg.init = InitialState::maxwell;
  cfg.n = 10000;
  cfg.seed = 300 + D;
  cfg.vhs_exponent = a;
  Engine<D, Model> e(cfg);
  on_two_threads(e);
  std::vector<double> per_block;
  for (int b = 1; b <= 40; ++b) {
    const double c0 = e.collisions_per_particle();
    e.run_until(5.0 * b);
    per_block.push_back((e.collisions_per_particle() - c0) / 5.0);
  }
  const auto [m, se] = mean_se(per_block);
  INFO("D = " << D << ", a = " << a << ": rate " << m << " +- " << se);
  REQUIRE(std::abs(m - 1.0) < t_threshold(1e-5, 40) * se);
  REQUIRE(se < 3e-3);
}

template <int D, class Model>
void check_relaxation(InitialState s, double a) {
  // KS distance of the speeds from Maxwell-Boltzmann at kT = mean m|v|^2 / D must fall
  // (d(T) < d(0)/2 unless the start is already Maxwellian) and the final p-value must be
  // > 1e-5. 70 cases: false-failure probability < 7e-4 (the KS law is slightly
  // conservative here: the exact constraints on momentum and energy reduce fluctuations).
  Config cfg;
  cfg.n = 10000;
  cfg.seed = 400 + D + 10 * static_cast<int>(s);
  cfg.vhs_exponent = a;
  cfg.init = s;
  Engine<D, Model> e(cfg);
  on_two_threads(e);
  const double kT = moment(e.particles(), 1) / D;
  const auto [d0, p0] = ks_maxwell(e.particles(), kT);
  e.run_until(25.0);
  const auto [d1, p1] = ks_maxwell(e.particles(), kT);
  INFO("D = " << D << ", state " << registry::name(s) << ", a = " << a << ": KS distance " << d0
              << " -> " << d1 << ", p = " << p1);
  if (s != InitialState::maxwell) REQUIRE(d1 < 0.5 * d0);
  REQUIRE(p1 > 1e-5);
}

template <int D>
void relax_all_states() {
  for (const auto& entry : registry::initial_states) {
    const InitialState s = entry.value;
    check_relaxation<D, HardSpheres>(s, 1.0);
    check_relaxation<D, VariableHardSpheres>(s, 0.5);
  }
}
}  // namespace

TEMPLATE_TEST_CASE_SIG("HS and VHS: equilibrium collision rate is exactly one per particle",
                       "[dsmc][physics]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  check_rate<D, HardSpheres>(1.0);
  check_rate<D, VariableHardSpheres>(0.5);
  check_rate<D, VariableHardSpheres>(0.2);
}

TEMPLATE_TEST_CASE_SIG("HS and VHS: every initial state relaxes to Maxwell-Boltzmann",
                       "[dsmc][physics]", ((int D), D), 2, 3, 4, 5, 6) {
  relax_all_states<D>();
}

TEMPLATE_TEST_CASE_SIG("A Maxwellian stays Maxwellian", "[dsmc][physics]", ((int D), D), 2, 3, 6) {
  // At 5 times the speed law passes KS (p > 1e-5 each) and m4 stays at D (D+2) (kT/m)^2
  // within 5 standard errors sd(|v|^4)/sqrt(N) (false failure < 1e-5 over the test).
  Config cfg;
  cfg.init = InitialState::maxwell;
  cfg.n = 20000;
  cfg.seed = 500 + D;
  Engine<D, HardSpheres> e(cfg);
  const double kT = moment(e.particles(), 1) / D;
  for (double t : {0.5, 1.0, 2.0, 5.0, 10.0}) {
    e.run_until(t);
    const auto [d, p] = ks_maxwell(e.particles(), kT);
    const double m4 = moment(e.particles(), 2), m8 = moment(e.particles(), 4);
    const double se = std::sqrt((m8 - m4 * m4) / cfg.n);
    INFO("t = " << t << ": KS p = " << p << ", m4 = " << m4 << " +- " << se);
    REQUIRE(p > 1e-5);
    REQUIRE(std::abs(m4 - D * (D + 2.0) * kT * kT) < 5 * se);
  }
}

TEST_CASE("1D: equal masses never relax, two masses do", "[dsmc][physics]") {
  // Equal masses: every collision keeps or swaps two velocities, so the sorted velocities
  // are exactly those of the start (HS and Maxwell molecules, 1e5 collisions).
  {
    Config cfg;
    cfg.n = 2000;
    cfg.init = InitialState::cube;
    Engine<1, HardSpheres> hs(cfg);
    Engine<1, MaxwellMolecules> mm(cfg);
    std::vector<double> v0;
    for (std::size_t i = 0; i < cfg.n; ++i) v0.push_back(hs.particles().velocity(i)[0]);
    std::sort(v0.begin(), v0.end());
    hs.run_until(100.0);
    mm.run_until(100.0);
    REQUIRE(hs.collisions() > 50000);
    for (const auto* e : {&hs.particles(), &mm.particles()}) {
      std::vector<double> v1;
      for (std::size_t i = 0; i < cfg.n; ++i) v1.push_back(e->velocity(i)[0]);
      std::sort(v1.begin(), v1.end());
      REQUIRE(v1 == v0);
    }
  }
  // Masses 1 and 3 from different temperatures (1.5 and 0.5): the species temperatures meet
  // at the mixture temperature 1 and each species becomes Gaussian with variance kT/m.
  // Temperatures: |T_s - 1| < 5 sd, sd = sqrt(2/n_s) (chi-square with n_s dof; false failure
  // < 1e-6); KS p > 1e-5 per species.
  Config cfg;
  cfg.n = 20000;
  cfg.seed = 9;
  cfg.init = InitialState::two_temp;
  cfg.initial.kT_species = {1.5, 0.5};
  cfg.initial.mass_ratio = 3.0;
  cfg.initial.fraction = 0.5;
  Engine<1, HardSpheres, Features{.species = true}> e(cfg);
  const auto [d0, p0] = ks_maxwell(e.particles(), 1.0, 0, 10000);
  e.run_until(60.0);
  const double T0 = moment(e.particles(), 1, 0, 10000);
  const double T1 = 3.0 * moment(e.particles(), 1, 10000, 20000);
  INFO("species temperatures " << T0 << ", " << T1);
  REQUIRE(std::abs(T0 - 1.0) < 5 * std::sqrt(2.0 / 10000));
  REQUIRE(std::abs(T1 - 1.0) < 5 * std::sqrt(2.0 / 10000));
  const auto [dl, pl] = ks_maxwell(e.particles(), 1.0, 0, 10000);
  const auto [dh, ph] = ks_maxwell(e.particles(), 1.0 / 3.0, 10000, 20000);
  REQUIRE(dl < 0.5 * d0);
  REQUIRE(pl > 1e-5);
  REQUIRE(ph > 1e-5);
}

TEST_CASE("3D mixture: species temperatures relax to a common value", "[dsmc][physics]") {
  // Masses 1 and 10, x1 = 0.3, kT 2.0 and 0.5: T_eq = 0.7 * 2 + 0.3 * 0.5 = 1.55.
  // |T_s - T_eq| < 5 sd, sd = T_eq sqrt(2/(D n_s)): false failure < 1e-6.
  Config cfg;
  cfg.n = 20000;
  cfg.seed = 10;
  cfg.init = InitialState::two_temp;
  cfg.initial.kT_species = {2.0, 0.5};
  cfg.initial.mass_ratio = 10.0;
  cfg.initial.fraction = 0.3;
  Engine<3, HardSpheres, Features{.species = true}> e(cfg);
  on_two_threads(e);
  e.run_until(40.0);
  const double Teq = 1.55;
  const double T0 = moment(e.particles(), 1, 0, 14000) / 3.0;
  const double T1 = 10.0 * moment(e.particles(), 1, 14000, 20000) / 3.0;
  INFO("species temperatures " << T0 << ", " << T1);
  REQUIRE(std::abs(T0 - Teq) < 5 * Teq * std::sqrt(2.0 / (3 * 14000.0)));
  REQUIRE(std::abs(T1 - Teq) < 5 * Teq * std::sqrt(2.0 / (3 * 6000.0)));
}
