// Tests of initial_state.hpp: zero momentum and exact energy for every state and D, parsing,
// and the defining property of each state (equal speeds, BKW fourth moment, populations).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hypergas/registry.hpp"
#include "hypergas/initial_state.hpp"

using namespace hypergas;

namespace {
template <int D, Features F>
void check_conserved(const Particles<D, F>& ps, double energy_expected) {
  Vec<D> mom = Vec<D>::Zero();
  double pscale = 0.0, e2 = 0.0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    mom += ps.mass(i) * ps.velocity(i);
    pscale += ps.mass(i) * ps.velocity(i).norm();
    e2 += ps.mass(i) * ps.velocity(i).squaredNorm();
  }
  REQUIRE(mom.norm() <= 1e-13 * pscale);
  REQUIRE(std::abs(0.5 * e2 - energy_expected) <= 1e-13 * energy_expected);
}
}  // namespace

TEST_CASE("initial states: names round-trip and unknown names throw", "[initial]") {
  for (auto name : registry::initial_state_names())
    REQUIRE(registry::name(registry::initial_state(name)) == name);
  REQUIRE(registry::initial_state("two-temp") == InitialState::two_temp);
  REQUIRE_THROWS_AS(registry::initial_state("maxwel"), InvalidInput);
  REQUIRE_THROWS_AS(registry::initial_state(""), InvalidInput);
}

TEMPLATE_TEST_CASE_SIG("initial states: zero momentum and exact energy in every D", "[initial]",
                       ((int D), D), 1, 2, 3, 4, 5, 6) {
  for (auto name : registry::initial_state_names()) {
    CAPTURE(name);
    const InitialState s = registry::initial_state(name);
    InitialParams prm;
    prm.kT = 1.7;
    Particles<D> ps(1000);
    Rng rng(7, D);
    initialize_velocities(ps, s, rng, prm);
    const double kTmean = initial_temperature<Features{}>(ps.size(), s, prm);
    check_conserved(ps, 0.5 * D * ps.size() * kTmean);

    // Species scene: two masses, per-population momentum and energy.
    Particles<D, Features{.species = true}> mix(1001);
    prm.mass_ratio = 3.0;
    prm.fraction = 0.3;
    if (D == 1 && s == InitialState::delta) {  // 701 + 300: odd count is impossible in 1D
      REQUIRE_THROWS_AS(initialize_velocities(mix, s, rng, prm), InvalidInput);
      continue;
    }
    initialize_velocities(mix, s, rng, prm);
    REQUIRE(mix.species(0) == 0);
    REQUIRE(mix.species(1000) == 1);
    REQUIRE(mix.mass(1000) == 3.0);
    REQUIRE(second_population_size<Features{.species = true}>(1001, s, prm) == 300);
    check_conserved(mix,
                    0.5 * D * 1001 * initial_temperature<Features{.species = true}>(1001, s, prm));
  }
}

TEMPLATE_TEST_CASE_SIG("delta shell: all speeds equal, odd counts closed", "[initial]",
                       ((int D), D), 2, 3, 6) {
  for (std::size_t n : {1000u, 1001u}) {
    Particles<D> ps(n);
    Rng rng(3);
    initialize_velocities(ps, InitialState::delta, rng);
    const double c = std::sqrt(double(D));  // kT = 1, m = 1: |v|^2 = D
    for (std::size_t i = 0; i < n; ++i) REQUIRE(std::abs(ps.velocity(i).norm() - c) < 1e-13);
    check_conserved(ps, 0.5 * D * n);
  }
}

TEMPLATE_TEST_CASE_SIG("BKW initial state has the BKW fourth moment", "[initial]", ((int D), D), 1,
                       2, 3, 4, 5, 6) {
  // f0 ~ |v|^2 exp(-v^2/(2K)), K = D/(D+2) (kT = m = 1): <v^4> = D(D+2) K (2 - K)
  // = D^2 (D+4)/(D+2) (BKW: Bobylev 1976; Krook & Wu 1977, generalised to D dims).
  // The sample m4 of 2e5 particles has standard error sd(v^4)/sqrt(n) (estimated from the
  // sample); |z| < 5 fails a correct sampler with probability 5.7e-7 per D.
  const std::size_t n = 200000;
  Particles<D> ps(n);
  Rng rng(11, D);
  initialize_velocities(ps, InitialState::bkw, rng);
  double m4 = 0.0, m8 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v2 = ps.velocity(i).squaredNorm();
    m4 += v2 * v2;
    m8 += v2 * v2 * v2 * v2;
  }
  m4 /= n;
  m8 /= n;
  const double expected = D * D * (D + 4.0) / (D + 2.0);
  const double se = std::sqrt((m8 - m4 * m4) / n);
  REQUIRE(std::abs(m4 - expected) < 5 * se);
}

TEST_CASE("two-temp: populations carry their own temperatures", "[initial]") {
  Particles<3> ps(1000);
  Rng rng(5);
  InitialParams prm;
  prm.kT_species = {2.0, 0.5};
  prm.fraction = 0.25;
  initialize_velocities(ps, InitialState::two_temp, rng, prm);
  double e0 = 0.0, e1 = 0.0;
  for (std::size_t i = 0; i < 750; ++i) e0 += 0.5 * ps.velocity(i).squaredNorm();
  for (std::size_t i = 750; i < 1000; ++i) e1 += 0.5 * ps.velocity(i).squaredNorm();
  REQUIRE(e0 == Approx(1.5 * 750 * 2.0).epsilon(1e-13));
  REQUIRE(e1 == Approx(1.5 * 250 * 0.5).epsilon(1e-13));
  REQUIRE(initial_temperature<Features{}>(1000, InitialState::two_temp, prm) ==
          Approx(0.75 * 2.0 + 0.25 * 0.5));
}

TEST_CASE("initial states: invalid parameters throw", "[initial]") {
  Particles<2> ps(10);
  Rng rng(1);
  InitialParams prm;
  prm.kT = -1.0;
  REQUIRE_THROWS_AS(initialize_velocities(ps, InitialState::maxwell, rng, prm), InvalidInput);
  prm = {};
  prm.fraction = 1.5;
  REQUIRE_THROWS_AS(initialize_velocities(ps, InitialState::two_temp, rng, prm), InvalidInput);
  Particles<1> one(1);
  REQUIRE_THROWS_AS(initialize_velocities(one, InitialState::maxwell, rng), InvalidInput);
}
