// Minimal DSMC runs: N = 2 in every D (and N = 1 rejected).
//
// Two particles at zero total momentum, m1 v1 = -m2 v2, keep |v1| and |v2| fixed for ever
// (energy and momentum conservation leave only the direction free), so the pair collides at
// the constant rate c |g|^a / (N - 1) = c |g|^a: the number of collisions by time T is
// Poisson with mean c |g| T (hard spheres). In D >= 2 the direction of v1 performs a random
// walk on the sphere whose stationary law is uniform, so <(v1_x / |v1|)^2> = 1/D; in D = 1
// (two masses) every collision reverses both velocities exactly.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "extreme/extreme_common.hpp"
#include "hypergas/dsmc/engine.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;

TEMPLATE_TEST_CASE_SIG("DSMC with N = 2: constant speeds, Poisson collision count, uniform "
                       "directions", "[dsmc][extreme]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  constexpr Features F{.species = (D == 1)};  // 1D: masses 1 and 3 (equal masses only swap)
  Config cfg;
  cfg.n = 2;
  cfg.init = InitialState::maxwell;
  cfg.initial.mass_ratio = 3.0;
  cfg.seed = 11 + D;
  // The initial states give each species zero momentum, which one particle cannot have with
  // energy; so in 1D the pair is built by hand: m0 = 1, m1 = 3, v0 = 3 u, v1 = -u.
  auto make = [&] {
    if constexpr (D == 1) {
      Particles<D, F> ps(2);
      ps.set_species_mass(1, 3.0);
      ps.set_species(1, 1);
      ps.velocity(0)[0] = 1.5;
      ps.velocity(1)[0] = -0.5;
      return Engine<D, HardSpheres, F>(cfg, std::move(ps));
    } else {
      return Engine<D, HardSpheres, F>(cfg);
    }
  };
  Engine<D, HardSpheres, F> e = make();
  const auto& p = e.particles();
  const double s1 = p.velocity(0).norm(), s2 = p.velocity(1).norm();
  const double g = (p.velocity(0) - p.velocity(1)).norm();
  const auto c0 = conserved(p);
  // K samples spaced by 10 mean collision times: the direction correlation after k
  // collisions is ((D - 3)/(D + 1))^k for hard spheres (<= 2e-4 for k = 10 in 6D), so the
  // samples are independent to that accuracy.
  const int K = 4000;
  const double spacing = 10.0 / (e.rate_constant() * g);
  double cos2 = 0.0, cos2sq = 0.0;
  for (int k = 1; k <= K; ++k) {
    e.run_until(k * spacing);
    REQUIRE(extreme::all_finite(p));
    REQUIRE(std::abs(p.velocity(0).norm() - s1) <= 1e-12 * s1);
    REQUIRE(std::abs(p.velocity(1).norm() - s2) <= 1e-12 * s2);
    const double c = p.velocity(0)[0] / p.velocity(0).norm();
    cos2 += c * c;
    cos2sq += c * c * c * c;
  }
  const auto [de, dp] = extreme::drifts<D>(c0, conserved(p));
  // Round-off: each collision rescales |g| by its sampled unit vector's norm, 1 + O(eps),
  // and those errors need not average out (the same pair collides every time), so the drift
  // after K collisions may grow like K eps; bound 4 eps K (~3.5e-11 for K = 4e4).
  const double roundoff = 4.0 * 2.2e-16 * static_cast<double>(e.collisions());
  INFO("D = " << D << ": energy drift " << de << ", momentum drift " << dp << ", bound " << roundoff);
  REQUIRE(de < roundoff);
  REQUIRE(dp < roundoff);
  // Poisson count with mean mu = c |g| T (~4e4): |count - mu| < 5 sqrt(mu), false-failure
  // probability 6e-7.
  const double mu = e.rate_constant() * g * e.time();
  INFO("D = " << D << ": collisions " << e.collisions() << ", Poisson mean " << mu);
  REQUIRE(std::abs(static_cast<double>(e.collisions()) - mu) < 5.0 * std::sqrt(mu));
  if constexpr (D >= 2) {
    // Mean of K independent cos^2 values vs 1/D within 5 standard errors (6e-7).
    const double m = cos2 / K, se = std::sqrt((cos2sq / K - m * m) / (K - 1.0));
    INFO("<cos^2> = " << m << " +- " << se << ", uniform 1/D = " << 1.0 / D);
    REQUIRE(std::abs(m - 1.0 / D) < 5.0 * se);
  } else {
    REQUIRE(std::abs(std::abs(p.velocity(0)[0]) - s1) <= 1e-12 * s1);
  }
}

TEST_CASE("DSMC rejects N < 2 with a clear error", "[dsmc][extreme]") {
  Config cfg;
  cfg.n = 1;
  REQUIRE_THROWS_AS((Engine<3, HardSpheres>(cfg)), InvalidInput);
  cfg.n = 0;
  REQUIRE_THROWS_AS((Engine<2, MaxwellMolecules>(cfg)), InvalidInput);
}
