// One DSMC system on several threads: the gas after every call is bit for bit the gas of
// the one-thread engine, for every thread count, model, scheme, species feature and
// dimension, and the self-check (a sequential replay of every parallel block) finds no
// disagreement. Deterministic: any difference is a defect.
//
// Small blocks (64 .. 512 candidates) on a few thousand particles make every path of the
// parallel schedule frequent: candidates deferred because an earlier chunk or an earlier
// deferred candidate holds one of their particles, raises of the majorant inside a block
// (the cube and two-beam starts raise it often while the tail forms), undoing of what later
// chunks applied after such a raise, and epochs cut by observation times.
#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <vector>

#include "hypergas/dsmc/engine.hpp"
#include "hypergas/observer.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;

namespace {

/// The velocity components (not the records' padding) as raw bits.
template <class E>
std::vector<std::uint64_t> velocity_bits(const E& e) {
  std::vector<std::uint64_t> out;
  const auto& p = e.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < E::dim; ++d) out.push_back(std::bit_cast<std::uint64_t>(p.velocity(i)[d]));
  return out;
}

struct Run {
  std::vector<std::uint64_t> v;
  std::uint64_t collisions = 0, candidates = 0, failures = 0;
  double time = 0.0;
  std::vector<double> seen;  // observed times and collision counts
};

struct Recorder : Observer {
  std::vector<double>* out;
  explicit Recorder(std::vector<double>* o) : out(o) {}
  void observe(const Snapshot& s) override {
    out->push_back(s.time);
    out->push_back(static_cast<double>(s.collisions));
  }
};

template <int D, class Model, Features F = Features{}>
Run run(const Config& cfg, int threads, std::uint32_t block, bool check) {
  Engine<D, Model, F> e(cfg);
  if (threads > 1) e.set_threads(threads, block);
  e.set_self_check(check);
  Run r;
  Recorder rec(&r.seen);
  e.run_until(1.5, &rec, 0.25);  // epochs cut at observation times
  e.run_until(3.0);
  r.v = velocity_bits(e);
  r.collisions = e.collisions();
  r.candidates = e.candidates();
  r.failures = e.self_check_failures();
  r.time = e.time();
  return r;
}

template <int D, class Model, Features F = Features{}>
void require_identical(Config cfg) {
  const Run ref = run<D, Model, F>(cfg, 1, 0, false);
  REQUIRE(ref.collisions > 1000);
  for (int T : {2, 3, 4, 7}) {
    for (std::uint32_t block : {64u, 512u}) {
      INFO("D = " << D << ", model " << Model::name << ", T = " << T << ", block " << block);
      const Run r = run<D, Model, F>(cfg, T, block, false);
      REQUIRE(r.collisions == ref.collisions);
      REQUIRE(r.candidates == ref.candidates);
      REQUIRE(r.time == ref.time);
      REQUIRE(r.seen == ref.seen);
      REQUIRE(r.v == ref.v);
    }
  }
}

Config small(std::size_t n, InitialState init, Scheme s) {
  Config cfg;
  cfg.n = n;
  cfg.seed = 11;
  cfg.init = init;
  cfg.scheme = s;
  cfg.dt = 0.02;
  return cfg;
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("DSMC on T threads equals the one-thread engine bit for bit", "[dsmc]",
                       ((int D), D), 1, 2, 3, 4, 5, 6) {
  for (Scheme s : {Scheme::exact, Scheme::ntc}) {
    const Config cube = small(3000, InitialState::cube, s);
    require_identical<D, HardSpheres>(cube);
    require_identical<D, VariableHardSpheres>(cube);
    require_identical<D, MaxwellMolecules>(cube);
  }
}

TEST_CASE("DSMC on T threads equals the one-thread engine with two species", "[dsmc]") {
  for (Scheme s : {Scheme::exact, Scheme::ntc}) {
    Config cfg = small(3000, InitialState::two_temp, s);
    cfg.initial.mass_ratio = 4.0;
    cfg.initial.fraction = 0.3;
    cfg.initial.kT_species = {1.0, 3.0};
    require_identical<1, HardSpheres, Features{.species = true}>(cfg);
    require_identical<3, HardSpheres, Features{.species = true}>(cfg);
    require_identical<6, VariableHardSpheres, Features{.species = true}>(cfg);
  }
}

TEST_CASE("DSMC parallel blocks replay to the sequential state (self-check)", "[dsmc]") {
  // The self-check replays every parallel block one candidate at a time on a copy of the
  // velocities at its start and compares bit for bit; it also checks where a raise of the
  // bound ended the block.
  for (Scheme s : {Scheme::exact, Scheme::ntc}) {
    const Config cfg = small(2000, InitialState::cube, s);
    const Run a = run<3, HardSpheres>(cfg, 3, 128, true);
    REQUIRE(a.collisions > 1000);
    REQUIRE(a.failures == 0);
    const Run b = run<6, VariableHardSpheres>(cfg, 2, 256, true);
    REQUIRE(b.failures == 0);
    // and the checked runs are the unchecked ones
    REQUIRE(a.v == run<3, HardSpheres>(cfg, 1, 0, false).v);
  }
}

TEST_CASE("DSMC threads: bad thread counts are refused", "[dsmc]") {
  Engine<3, HardSpheres> e(small(100, InitialState::maxwell, Scheme::exact));
  REQUIRE_THROWS_AS(e.set_threads(0), InvalidInput);
  REQUIRE_THROWS_AS(e.set_threads(257), InvalidInput);
  e.set_threads(2);  // the exact scheme runs the one-thread loop without a block size
  REQUIRE(e.threads() == 2);
  REQUIRE(e.block_size() == 0);
  e.set_threads(2, 64);
  REQUIRE(e.threads() == 2);
  REQUIRE(e.block_size() == 64);
}
