// Conservation over long runs: after 1e7 collisions in every D the total momentum has
// drifted by <= 1e-12 of the momentum scale sum m|v| and the energy by <= 1e-12 relative.
// (A deterministic check of round-off: each collision changes the pair's energy by a few
// ulps; 1e7 random-sign errors of relative size 1e-16 x (2/N) stay far below the bound.)
// The non-long case does 1e6 collisions per D and model; the [long] case 1e7.
#include <catch2/catch.hpp>

#include <cmath>

#include "hypergas/conserved.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "physics/test_dsmc_common.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;

namespace {
struct Drift {
  double collisions = 0, momentum = 1, energy = 1;
};

template <int D, class Model, Features F = Features{}>
Drift run_collisions(double target, InitialState init) {
  Config cfg;
  cfg.n = 10000;
  cfg.seed = 2024 + D;
  cfg.init = init;
  cfg.initial.mass_ratio = 7.0;
  cfg.initial.fraction = 0.4;
  Engine<D, Model, F> e(cfg);
  const auto c0 = conserved(e.particles());
  while (double(e.collisions()) < target)  // out of equilibrium the rate differs from 1
    e.run_until(e.time() + 2.0 * (target - double(e.collisions())) / cfg.n + 1.0);
  const auto c1 = conserved(e.particles());
  return {double(e.collisions()), momentum_drift(c0, c1), energy_rel_drift(c0, c1)};
}

template <int D>
void all_models(double target) {
  Drift d[3];
  dsmc_test::for_replicas(3, [&](int r) {  // no Catch assertions inside threads
    if (r == 0) d[0] = run_collisions<D, HardSpheres>(target, InitialState::delta);
    if (r == 1) d[1] = run_collisions<D, VariableHardSpheres>(target, InitialState::cube);
    if (r == 2)
      d[2] = run_collisions<D, MaxwellMolecules, Features{.species = true}>(target,
                                                                            InitialState::two_temp);
  });
  for (const auto& x : d) {
    INFO("D = " << D << ", collisions " << x.collisions << ", momentum drift " << x.momentum
                << ", energy drift " << x.energy);
    REQUIRE(x.collisions >= target);
    REQUIRE(x.momentum <= 1e-12);
    REQUIRE(x.energy <= 1e-12);
  }
}
}  // namespace

TEMPLATE_TEST_CASE_SIG("DSMC conservation over 1e6 collisions", "[dsmc][physics]", ((int D), D), 1,
                       2, 3, 4, 5, 6) {
  all_models<D>(1e6);
}

TEMPLATE_TEST_CASE_SIG("DSMC conservation over 1e7 collisions", "[dsmc][physics][long]",
                       ((int D), D), 1, 2, 3, 4, 5, 6) {
  all_models<D>(1e7);
}
