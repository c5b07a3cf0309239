// EDMD in dense states: 3D hard spheres compressed (Lubachevsky–Stillinger) from a fluid at
// eta = 0.30 to 99 % of random close packing, eta = 0.99 * 0.64 = 0.6336, then run.
//
// Checked: the packing is reached; no pair overlaps (all-pairs check after compression and
// after the run); energy conserved to 1e-12 relative and momentum to round-off; the event
// rate is finite and the run does not stall (it covers its time span with a bounded number
// of collisions); and a physical result near jamming: free-volume theory gives
// Z = D / (1 - eta/eta_J) + O(1) for a state caged near its jamming density eta_J
// (Salsburg & Wood, J. Chem. Phys. 37, 798 (1962); Donev, Torquato & Stillinger, Phys.
// Rev. E 71, 011105 (2005)). The measured Z therefore fixes eta_J = eta / (1 - D/Z), which
// must lie in the range of jamming densities of fast LS compressions, 0.634-0.66 (Skoge,
// Donev, Stillinger & Torquato, Phys. Rev. E 74, 041127 (2006)); and Z must be far above
// the fluid branch (Carnahan-Starling: 36 at this eta), i.e. the compression produced a
// jammed-glass state rather than a fluid. The run is deterministic (fixed seed); the
// tolerances are physical ranges, not statistical ones.
#include <catch2/catch.hpp>

#include <cmath>

#include "hypergas/edmd/compression.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/edmd/observables.hpp"

using namespace hypergas;

TEST_CASE("EDMD at 99% of random close packing in 3D: no overlap, no stall, free-volume Z",
          "[edmd][extreme]") {
  constexpr int D = 3;
  edmd::Config cfg;
  cfg.n = 1000;
  cfg.packing = 0.30;
  cfg.seed = 3;
  cfg.growth_rate = 0.5;  // fast growth avoids crystallisation (random packings, LS 1990)
  edmd::Engine<D> e(cfg);
  e.run_until(2.0);  // melt the lattice start
  const double eta = 0.99 * edmd::jamming_packing(D);
  edmd::compress(e, std::cbrt(eta / cfg.packing), cfg);
  REQUIRE(e.packing() == Approx(eta).epsilon(1e-9));
  REQUIRE_NOTHROW(e.check_overlaps());

  e.reset_observables();
  const double e0 = e.kinetic_energy();
  const auto p0 = e.momentum();
  const double t0 = e.time();
  e.run_until(t0 + 0.5);
  REQUIRE_NOTHROW(e.check_overlaps());
  REQUIRE(std::abs(e.kinetic_energy() / e0 - 1.0) < 1e-12);
  REQUIRE((e.momentum() - p0).norm() < 1e-12 * std::sqrt(2.0 * e0 * cfg.n));

  const double Z = e.pressure_Z();
  const double rate = e.collision_rate();
  const double eta_J = eta / (1.0 - D / Z);
  INFO("Z = " << Z << ", collisions per particle and unit time " << rate << ", eta_J = "
              << eta_J << ", collisions " << e.window_collisions());
  REQUIRE(std::isfinite(Z));
  REQUIRE(e.time() == t0 + 0.5);
  REQUIRE(e.window_collisions() > 10000);    // the gas moves ...
  REQUIRE(e.window_collisions() < 20000000);  // ... and the event rate stays finite
  REQUIRE(Z > 5.0 * edmd::carnahan_starling_Z(eta));
  REQUIRE(eta_J > 0.634);
  REQUIRE(eta_J < 0.66);
}

// The 6D counterpart: N = 400 hyperspheres at 90 % of the 6D jamming density (0.20, Skoge
// et al. 2006), eta = 0.18, reached by the constructor's LS compression from the D_6
// lattice start (growth rate 0.5). The box is 2.4 sigma wide, below 3 cells, so this also
// exercises the one-cell path with all 3^6 periodic images. Fast compression in 6D does not
// crystallise; the state is a dense (metastable or glassy) disordered one, the densest this
// engine reaches in a test's time. Checked as in 3D: no overlap, energy and momentum
// conserved, a finite event rate over 0.5 time units, and the free-volume jamming density
// eta_J = eta / (1 - D/Z) near 0.20 (measured 0.199 at N = 400 and 800; at 90 % of eta_J
// the free-volume form is accurate to a few per cent, hence the range 0.19-0.215).
TEST_CASE("EDMD at 90% of the 6D jamming density: no overlap, no stall, free-volume Z",
          "[edmd][extreme]") {
  constexpr int D = 6;
  edmd::Config cfg;
  cfg.n = 400;
  cfg.packing = 0.9 * edmd::jamming_packing(D);
  cfg.seed = 3;
  cfg.growth_rate = 0.5;
  edmd::Engine<D> e(cfg);
  REQUIRE(e.packing() == Approx(cfg.packing).epsilon(1e-9));
  REQUIRE(e.cells_per_side() == 1);
  REQUIRE_NOTHROW(e.check_overlaps());
  e.run_until(0.2);
  e.reset_observables();
  const double e0 = e.kinetic_energy();
  const auto p0 = e.momentum();
  e.run_until(0.7);
  REQUIRE_NOTHROW(e.check_overlaps());
  REQUIRE(std::abs(e.kinetic_energy() / e0 - 1.0) < 1e-12);
  REQUIRE((e.momentum() - p0).norm() < 1e-12 * std::sqrt(2.0 * e0 * cfg.n));
  const double Z = e.pressure_Z();
  const double eta_J = cfg.packing / (1.0 - D / Z);
  INFO("Z = " << Z << ", collisions per particle and unit time " << e.collision_rate()
              << ", eta_J = " << eta_J << ", collisions " << e.window_collisions());
  REQUIRE(std::isfinite(Z));
  REQUIRE(e.window_collisions() > 5000);
  REQUIRE(e.window_collisions() < 20000000);
  REQUIRE(eta_J > 0.19);
  REQUIRE(eta_J < 0.215);
}
