// Minimal EDMD runs: N = 2 in every D, and the smallest legal box (side 2 diameters).
//
// Two equal spheres at zero total momentum keep |v1| = |v2| (energy and momentum), so the
// relative coordinate r = x1 - x2 is a billiard: it moves freely at the constant speed
// |g| = 2 |v1| in the torus of side L and reflects specularly off the ball |r| = sigma (the
// Sinai billiard; ergodic). Santalo's formula gives its mean free path exactly,
//   l = |Q| |S^(D-1)| / (|dQ| |B^(D-1)|),  |Q| = L^D - omega_D sigma^D, |dQ| = D omega_D sigma^(D-1),
// (omega_D the unit-ball volume; l = |Q| / (2 sigma) in 2D, |Q| / (pi sigma^2) in 3D; e.g.
// N. Chernov, J. Stat. Phys. 88, 1 (1997)), so the collision rate is |g| / l. In 1D the
// two rods exchange velocities, and collide exactly every (L - 2 sigma) / |g|.
// Each run checks: no overlap after any event (debug check), finite velocities, energy and
// momentum conserved to round-off, and the collision rate.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "extreme/extreme_common.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/geometry.hpp"

using namespace hypergas;

namespace {
/// Packing fraction of 2 unit spheres in a cube of side L.
double packing_for_side(int D, double L) { return 2.0 * ball_volume(D, 1.0) / std::pow(L, D); }
}  // namespace

TEMPLATE_TEST_CASE_SIG("EDMD with N = 2: Santalo collision rate, conservation, no overlap",
                       "[edmd][extreme]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  const double L = D == 1 ? 2.5 : 2.2;
  edmd::Config cfg;
  cfg.n = 2;
  cfg.packing = packing_for_side(D, L);
  cfg.seed = 3 + D;
  cfg.debug_overlap = true;
  edmd::Engine<D> e(cfg);
  REQUIRE(std::abs(e.box_side() - L) < 1e-12 * L);
  const auto& p = e.particles();
  const double g = (p.velocity(0) - p.velocity(1)).norm();
  const double e0 = e.kinetic_energy();
  // Mean free time of the relative coordinate.
  double tau;
  if constexpr (D == 1) {
    tau = (L - 2.0) / g;
  } else {
    const double Q = std::pow(L, D) - unit_ball_volume(D);
    const double ell = Q * D * unit_ball_volume(D) / (D * unit_ball_volume(D) * unit_ball_volume(D - 1));
    tau = ell / g;
  }
  // B batches of 4000 mean free times: batch means of the rate are ~independent.
  const int B = 20;
  std::vector<double> rate(B);
  std::uint64_t c0 = e.collisions();
  for (int b = 0; b < B; ++b) {
    const double t0 = e.time();
    e.run_until(t0 + 4000.0 * tau);
    rate[b] = static_cast<double>(e.collisions() - c0) * tau / (e.time() - t0);
    c0 = e.collisions();
    REQUIRE(extreme::all_finite(p));
  }
  // Round-off: ~1e5 collisions, each changing the energy by a few ulp; bound 4 eps K.
  const double K = static_cast<double>(e.collisions());
  INFO("D = " << D << ": " << K << " collisions, energy drift " << (e.kinetic_energy() - e0) / e0
              << ", momentum " << e.momentum().norm() / g);
  REQUIRE(std::abs(e.kinetic_energy() - e0) < 4.0 * 2.2e-16 * K * e0);
  REQUIRE(e.momentum().norm() < 4.0 * 2.2e-16 * K * g);
  // With zero momentum K_E = g^2 / 4 (unit masses): |g| carries half the relative energy
  // error, so the same round-off bound applies (2 eps per collision).
  REQUIRE(std::abs((p.velocity(0) - p.velocity(1)).norm() - g) < 2.0 * 2.2e-16 * K * g);
  const auto [m, se] = extreme::mean_se(rate);
  INFO("D = " << D << ": collisions per mean free time " << m << " +- " << se << " (Santalo: 1)");
  if constexpr (D == 1) {
    REQUIRE(std::abs(m - 1.0) < 1e-3);  // periodic: exact up to the batch edges
  } else {
    // Student t test over B batches, false-failure probability 1e-4.
    REQUIRE(std::abs(m - 1.0) < extreme::t_threshold(1e-4, B) * se);
    REQUIRE(se < 0.02);
  }
}

TEMPLATE_TEST_CASE_SIG("EDMD smallest legal box: side 2 diameters accepted, below rejected",
                       "[edmd][extreme]", ((int D), D), 2, 3, 6) {
  edmd::Config cfg;
  cfg.n = 2;
  cfg.packing = packing_for_side(D, 2.0 * (1.0 + 1e-9));
  cfg.debug_overlap = true;
  edmd::Engine<D> e(cfg);
  const double e0 = e.kinetic_energy();
  e.run_until(200.0);
  REQUIRE(e.collisions() > 10);
  REQUIRE(extreme::all_finite(e.particles()));
  REQUIRE(std::abs(e.kinetic_energy() - e0) < 1e-12 * e0);
  cfg.packing = packing_for_side(D, 1.9);
  REQUIRE_THROWS_AS(edmd::Engine<D>(cfg), InvalidInput);
}
