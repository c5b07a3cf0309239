// Unit tests of the DSMC engine: conservation over 1e5 collisions in every D, model and
// scheme, observer timing, reproducibility, storage cost and input validation.
#include <catch2/catch.hpp>

#include <limits>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hypergas/registry.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/dsmc/engine.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;

namespace {
template <int D, class Model, Features F = Features{}>
void check_conservation(Scheme scheme, InitialState init) {
  Config cfg;
  cfg.n = 2000;
  cfg.seed = 99;
  cfg.scheme = scheme;
  cfg.dt = 0.05;
  cfg.init = init;
  cfg.initial.mass_ratio = 3.0;
  cfg.initial.fraction = 0.5;
  Engine<D, Model, F> e(cfg);
  const auto c0 = conserved(e.particles());
  e.run_until(100.0);  // ~1e5 collisions
  const auto c1 = conserved(e.particles());
  REQUIRE(e.collisions() > 50000);
  REQUIRE(momentum_drift(c0, c1) <= 1e-12);
  REQUIRE(energy_rel_drift(c0, c1) <= 1e-12);
  REQUIRE(e.time() == 100.0);
}

struct Recorder : Observer {
  std::vector<double> times;
  std::vector<double> cpp;
  int dim = 0;
  void observe(const Snapshot& s) override {
    times.push_back(s.time);
    cpp.push_back(s.collisions_per_particle);
    dim = s.dim;
  }
};
}  // namespace

TEMPLATE_TEST_CASE_SIG("DSMC conserves momentum and energy to round-off", "[dsmc]", ((int D), D), 1,
                       2, 3, 4, 5, 6) {
  for (Scheme s : {Scheme::exact, Scheme::ntc}) {
    check_conservation<D, HardSpheres>(s, InitialState::cube);
    check_conservation<D, MaxwellMolecules>(s, InitialState::beams);
    check_conservation<D, VariableHardSpheres>(s, InitialState::bimaxwell);
    check_conservation<D, HardSpheres, Features{.species = true}>(s, InitialState::two_temp);
  }
}

TEST_CASE("DSMC observers: called at multiples of every, never between", "[dsmc]") {
  Config cfg;
  cfg.init = InitialState::maxwell;
  cfg.n = 1000;
  Engine<3, HardSpheres> e(cfg);
  Recorder rec;
  e.run_until(1.0, &rec, 0.25);
  e.run_until(2.0, &rec, 0.25);
  REQUIRE(rec.dim == 3);
  REQUIRE(rec.times.size() == 9);  // 0, 0.25, ..., 2
  for (std::size_t k = 0; k < rec.times.size(); ++k) REQUIRE(rec.times[k] == Approx(0.25 * k));
  REQUIRE(std::is_sorted(rec.cpp.begin(), rec.cpp.end()));
  REQUIRE(rec.cpp.front() == 0.0);
  REQUIRE_THROWS_AS(e.run_until(3.0, &rec, 0.0), InvalidInput);
  // The engine concept's rules (schedule.hpp): the grid starts at the time of the call,
  // `every` is rounded to divide the span, the last instant is the end time exactly, and a
  // time in the past or not finite is rejected.
  Recorder late;
  e.run_until(2.1);
  e.run_until(2.9, &late, 0.25);
  REQUIRE(late.times.size() == 4);  // 0.8 / 0.25 rounds to 3 intervals: 2.1, 2.37, 2.63, 2.9
  for (std::size_t k = 0; k < late.times.size(); ++k)
    REQUIRE(late.times[k] == Approx(2.1 + (2.9 - 2.1) / 3.0 * k));
  REQUIRE(late.times.back() == 2.9);
  REQUIRE(e.time() == 2.9);
  REQUIRE_THROWS_AS(e.run_until(2.0), InvalidInput);
  REQUIRE_THROWS_AS(e.run_until(std::numeric_limits<double>::infinity()), InvalidInput);
}

TEST_CASE("DSMC species snapshots carry species and masses", "[dsmc]") {
  struct SpeciesCheck : Observer {
    int n_species = 0;
    double w1 = 0;
    void observe(const Snapshot& s) override {
      n_species = s.n_species;
      w1 = s.inverse_mass(s.n - 1);
    }
  } chk;
  Config cfg;
  cfg.init = InitialState::maxwell;
  cfg.n = 100;
  cfg.initial.mass_ratio = 4.0;
  cfg.initial.fraction = 0.5;
  Engine<1, HardSpheres, Features{.species = true}> e(cfg);
  e.run_until(0.5, &chk, 0.5);
  REQUIRE(chk.n_species == 2);
  REQUIRE(chk.w1 == 0.25);
}

TEST_CASE("DSMC runs are reproducible from the seed", "[dsmc]") {
  Config cfg;
  cfg.n = 500;
  cfg.seed = 5;
  cfg.init = InitialState::delta;
  Engine<4, HardSpheres> a(cfg), b(cfg);
  a.run_until(1.0);
  a.run_until(3.0);
  b.run_until(1.0);
  b.run_until(3.0);  // epochs end at the requested times: same calls, same stream
  REQUIRE(a.collisions() == b.collisions());
  for (std::size_t i = 0; i < cfg.n; ++i)
    REQUIRE(a.particles().velocity(i) == b.particles().velocity(i));
  cfg.seed = 6;
  Engine<4, HardSpheres> c(cfg);
  c.run_until(3.0);
  REQUIRE(c.particles().velocity(0) != a.particles().velocity(0));
}

TEST_CASE("DSMC storage: no positions, 32 bytes per particle in 3D", "[dsmc]") {
  Config cfg;
  cfg.n = 1000;
  Engine<3, HardSpheres> e(cfg);
  REQUIRE(e.bytes_per_particle() == 32.0);
  // The state array holds velocities only: 4 doubles (3 + padding) per particle.
  static_assert(Particles<3>::stride == 4 && Particles<3>::velocity_offset == 0);
  Engine<6, HardSpheres> e6(cfg);
  REQUIRE(e6.bytes_per_particle() == 64.0);
}

TEST_CASE("DSMC: bad configurations throw InvalidInput", "[dsmc]") {
  Config cfg;
  cfg.n = 1;
  REQUIRE_THROWS_AS((Engine<3, HardSpheres>(cfg)), InvalidInput);
  cfg.n = 100;
  cfg.vhs_exponent = 2.0;
  REQUIRE_THROWS_AS((Engine<3, VariableHardSpheres>(cfg)), InvalidInput);
  cfg.vhs_exponent = 0.5;
  cfg.scheme = Scheme::ntc;
  cfg.dt = 0.0;
  REQUIRE_THROWS_AS((Engine<3, HardSpheres>(cfg)), InvalidInput);
  REQUIRE(registry::scheme("ntc") == Scheme::ntc);
  REQUIRE(registry::name(Scheme::exact) == "exact");
  REQUIRE_THROWS_AS(registry::scheme("euler"), InvalidInput);
  // A gas at rest has no time unit.
  Config rest;
  rest.n = 10;
  REQUIRE_THROWS_AS((Engine<2, HardSpheres>(rest, Particles<2>(10))), InvalidInput);
}

// The time unit is defined in the centre-of-mass frame (dsmc/time_unit.hpp), so given
// particles must have zero total momentum to rounding: |P| <= 1e-9 sqrt(M sum m v^2).
TEST_CASE("DSMC from given particles: zero total momentum required", "[dsmc]") {
  using Catch::Matchers::Contains;
  Config cfg;
  Particles<3> p(100);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < 3; ++k) p.velocity(i)[k] = std::sin(1.0 + 3.0 * double(i) + k);
  Vec<3> mean = Vec<3>::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) mean += p.velocity(i) / double(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) p.velocity(i) -= mean;
  REQUIRE_NOTHROW((Engine<3, HardSpheres>(cfg, p)));
  Particles<3> drift = p;  // a residual of 1e-12 of the scale passes, 1e-6 does not
  drift.velocity(0)[1] += 1e-12;
  REQUIRE_NOTHROW((Engine<3, HardSpheres>(cfg, drift)));
  drift.velocity(0)[1] += 1e-6;
  REQUIRE_THROWS_WITH((Engine<3, HardSpheres>(cfg, drift)),
                      Contains("the total momentum must be zero"));
  Particles<3> shifted = p;
  for (std::size_t i = 0; i < p.size(); ++i) shifted.velocity(i)[0] += 1.0;
  REQUIRE_THROWS_AS((Engine<3, HardSpheres>(cfg, shifted)), InvalidInput);
  REQUIRE_THROWS_WITH((Engine<3, HardSpheres>(cfg, Particles<3>(10))),
                      Contains("velocities must not all be zero"));
  // Two masses: m0 = 1, m1 = 3; v0 = 1.5, v1 = -0.5 is at rest in the mean, v1 = +0.5 is not.
  constexpr Features S{.species = true};
  Particles<1, S> q(2);
  q.set_species_mass(1, 3.0);
  q.set_species(1, 1);
  q.velocity(0)[0] = 1.5;
  q.velocity(1)[0] = -0.5;
  REQUIRE_NOTHROW((Engine<1, HardSpheres, S>(cfg, q)));
  q.velocity(1)[0] = 0.5;
  REQUIRE_THROWS_WITH((Engine<1, HardSpheres, S>(cfg, q)),
                      Contains("the total momentum must be zero"));
}

// The engine tests a batch of candidates at once and re-tests those that share a particle
// with a collision taken before them (each epoch, with its bound G, starts a new batch). The
// self-check re-tests every pending candidate against the state of the moment before each
// step; a missed re-test shows up as a failure. Small N makes shared particles frequent
// (N = 3: nearly every later candidate in a batch shares one with a collision), the cube
// start makes the bound rise while the tail forms (G changes between calls). Deterministic: any
// failure is a defect, so the bound is exactly 0 (removing the re-test loop gives hundreds).
TEMPLATE_TEST_CASE_SIG("DSMC batches decide each candidate with the state of its turn", "[dsmc]",
                       ((int D), D), 1, 3, 6) {
  for (std::size_t n : {std::size_t(3), std::size_t(5), std::size_t(64)}) {
    for (Scheme s : {Scheme::exact, Scheme::ntc}) {
      Config cfg;
      cfg.n = n;
      cfg.seed = 7;
      cfg.scheme = s;
      cfg.dt = 0.05;
      cfg.init = InitialState::cube;
      Engine<D, HardSpheres> hs(cfg);
      hs.set_self_check(true);
      hs.run_until(20000.0 / static_cast<double>(n));
      REQUIRE(hs.collisions() > 5000);
      REQUIRE(hs.self_check_failures() == 0);
      Engine<D, VariableHardSpheres> vhs(cfg);  // a = 0.5
      vhs.set_self_check(true);
      vhs.run_until(20000.0 / static_cast<double>(n));
      REQUIRE(vhs.self_check_failures() == 0);
    }
  }
}
