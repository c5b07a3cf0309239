// Large runs ([long]): 1e7 DSMC particles in 3D and 1e6 EDMD spheres in 3D, with the memory
// per particle reported (engine accounting and the process's peak resident set).
// Physical checks: DSMC at equilibrium collides once per particle per unit time (the time
// unit): 2 collisions / N at t = 1 is 1 within 5 Poisson standard deviations (sqrt(2/N)
// relative; false-failure probability 6e-7); EDMD at eta = 0.2618 gives Carnahan-Starling's
// Z = 3.2625 (J. Chem. Phys. 51, 635 (1969)) within 1 % (CS accuracy ~0.1 %, finite-size
// and statistical errors < 0.3 % at N = 1e6 over 2 mean free times per particle).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>

#include "extreme/extreme_common.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/edmd/observables.hpp"

using namespace hypergas;

namespace {
/// Resets the peak resident set size (Linux >= 4.0; ignored elsewhere), so that each test
/// case reports its own peak.
void reset_peak_rss() { std::ofstream("/proc/self/clear_refs") << "5"; }
/// Peak resident set size of this process (bytes), from /proc/self/status (0 if unknown).
double peak_rss_bytes() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmHWM:", 0) == 0) return 1024.0 * std::stod(line.substr(6));
  return 0.0;
}
}  // namespace

TEST_CASE("DSMC with 1e7 particles in 3D", "[dsmc][extreme][long]") {
  reset_peak_rss();
  dsmc::Config cfg;
  cfg.n = 10000000;
  cfg.init = InitialState::maxwell;
  cfg.seed = 99;
  dsmc::Engine<3, dsmc::HardSpheres> e(cfg);
  const auto c0 = conserved(e.particles());
  e.run_until(1.0);
  const auto [de, dp] = extreme::drifts<3>(c0, conserved(e.particles()));
  WARN("DSMC 3D N = 1e7: " << e.bytes_per_particle() << " bytes/particle (engine), peak RSS "
                           << peak_rss_bytes() / cfg.n << " bytes/particle, " << e.collisions()
                           << " collisions");
  REQUIRE(extreme::all_finite(e.particles()));
  REQUIRE(de < 1e-12);
  REQUIRE(dp < 1e-12);
  REQUIRE(std::abs(e.collisions_per_particle() - 1.0) < 5.0 * std::sqrt(2.0 / cfg.n));
}

TEST_CASE("EDMD with 1e6 spheres in 3D", "[edmd][extreme][long]") {
  reset_peak_rss();
  edmd::Config cfg;
  cfg.n = 1000000;
  cfg.packing = 0.2618;
  cfg.seed = 5;
  edmd::Engine<3> e(cfg);
  e.run_until(1.0);  // leave the lattice start
  e.reset_observables();
  const double e0 = e.kinetic_energy();
  e.run_until(1.3);
  WARN("EDMD 3D N = 1e6: " << e.bytes_per_particle() << " bytes/particle (engine), peak RSS "
                           << peak_rss_bytes() / cfg.n << " bytes/particle, Z = "
                           << e.pressure_Z() << " (CS " << edmd::carnahan_starling_Z(0.2618)
                           << "), " << e.collisions() << " collisions");
  REQUIRE(extreme::all_finite(e.particles()));
  REQUIRE(std::abs(e.kinetic_energy() - e0) < 1e-10 * e0);
  REQUIRE(std::abs(e.pressure_Z() / edmd::carnahan_starling_Z(0.2618) - 1.0) < 0.01);
}
