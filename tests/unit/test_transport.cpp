// The pieces of the Green-Kubo transport measurement: collective fluxes kept by the
// collisions equal to fluxes summed from the velocities (bit for bit), a trajectory the
// fluxes do not change, the block FFT correlator against the direct sum over origins, and
// the first Sonine reference values.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "hypergas/analysis/correlator.hpp"
#include "hypergas/analysis/transport_recorder.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/tally/fluxes.hpp"
#include "hypergas/tally/tally.hpp"

using namespace hypergas;

namespace {

/// Asks the engine to keep collective fluxes made at its first snapshot; later snapshots
/// compare them with a fresh sum over the velocities.
struct FluxCheck final : Observer {
  int compared = 0, equal = 0;
  std::unique_ptr<tally::Fluxes> made;
  void observe(const Snapshot& s) override {
    tally::Fluxes fresh(s.dim, 1.0);
    for (std::size_t i = 0; i < s.n; ++i) fresh.add(s.velocities + i * std::size_t(s.stride), 1);
    if (!s.tally->fluxes) {
      made = std::make_unique<tally::Fluxes>(fresh);
      return;
    }
    ++compared;
    equal += (*s.tally->fluxes == fresh);
  }
  void request(tally::Requests& r) override {
    if (made) r.set_fluxes(std::move(made));
  }
};

template <int D, class Model>
void check_fluxes_kept(int threads) {
  dsmc::Config cfg;
  cfg.n = 3000;
  cfg.seed = 11;
  cfg.init = InitialState::beams;
  dsmc::Engine<D, Model> e(cfg);
  e.set_threads(threads);
  FluxCheck chk;
  e.run_until(3.0, &chk, 0.25);
  REQUIRE(chk.compared == 12);
  REQUIRE(chk.equal == chk.compared);
}

}  // namespace

TEST_CASE("Fluxes: kept by the collisions equal the sums over the velocities", "[transport]") {
  check_fluxes_kept<2, dsmc::HardSpheres>(1);
  check_fluxes_kept<3, dsmc::HardSpheres>(2);
  check_fluxes_kept<3, dsmc::MaxwellMolecules>(1);
  check_fluxes_kept<5, dsmc::VariableHardSpheres>(1);
  check_fluxes_kept<6, dsmc::HardSpheres>(1);
}

TEST_CASE("Fluxes: the trajectory is the same with and without them", "[transport]") {
  dsmc::Config cfg;
  cfg.n = 5000;
  cfg.seed = 3;
  cfg.init = InitialState::beams;
  dsmc::Engine<3, dsmc::HardSpheres> a(cfg), b(cfg);
  FluxCheck chk;
  struct Nothing final : Observer {
    void observe(const Snapshot&) override {}
  } nothing;
  a.run_until(4.0, &chk, 0.5);
  b.run_until(4.0, &nothing, 0.5);  // the same stops (an epoch ends at each)
  REQUIRE(a.collisions() == b.collisions());
  REQUIRE(a.particles().velocity_data() == b.particles().velocity_data());
}

TEST_CASE("Fluxes: an exchange adds new terms and removes old ones exactly", "[transport]") {
  tally::Fluxes f(3, 1.0), g(3, 1.0);
  const double oi[3] = {0.3, -1.2, 2.0}, oj[3] = {-0.7, 0.4, 1e3}, ni[3] = {1.1, 0.1, -0.5},
               nj[3] = {-1.5, -0.9, 1e3 + 1.0};
  f.add(oi, 1), f.add(oj, 1);
  f.exchange<3>(oi, oj, ni, nj);  // |v|^3 ~ 1e9 takes the general path
  g.add(nj, 1), g.add(ni, 1);
  REQUIRE(f == g);
  REQUIRE(f.value(f.stress_index(0, 1)) == Approx(1.1 * 0.1 + 1.5 * 0.9).epsilon(1e-9));
}

TEST_CASE("BlockCorrelator: every lag over every origin, as the direct sum", "[transport]") {
  // three groups of AR(1) series of different lengths; frames not a multiple of the lags
  const std::size_t K = 48, F = 1000;
  const std::vector<int> group{0, 1, 1, 2, 2, 2};
  Rng r(5);
  std::vector<std::vector<double>> x(group.size(), std::vector<double>(F));
  for (auto& s : x) {
    double y = 0.0;
    for (auto& v : s) v = y = 0.9 * y + r.normal();
  }
  analysis::BlockCorrelator c(group, K, F, 4);
  std::vector<double> frame(group.size());
  for (std::size_t t = 0; t < F; ++t) {
    for (std::size_t s = 0; s < group.size(); ++s) frame[s] = x[s][t];
    c.push(frame.data());
  }
  c.finish();
  REQUIRE(c.stretches() == 4);
  for (int g = 0; g < 3; ++g) {
    const std::vector<double> m = c.mean(g);
    for (std::size_t k = 0; k < K; ++k) {
      double sum = 0.0, count = 0.0;
      for (std::size_t s = 0; s < group.size(); ++s) {
        if (group[s] != g) continue;
        for (std::size_t n = 0; n + k < F; ++n) sum += x[s][n] * x[s][n + k];
        count += double(F - k);
      }
      REQUIRE(m[k] == Approx(sum / count).epsilon(1e-10).margin(1e-12));
    }
    // each stretch averages its own origins: lag 0 of stretch j is the mean square of
    // its frames (250 each here: blocks of 48, 21 blocks, 5 per stretch, the last 6)
    for (int j = 0; j < 4; ++j) {
      const std::size_t lo = std::size_t(j) * 5 * K, hi = j == 3 ? F : lo + 5 * K;
      double sum = 0.0, count = 0.0;
      for (std::size_t s = 0; s < group.size(); ++s)
        if (group[s] == g)
          for (std::size_t n = lo; n < hi; ++n) sum += x[s][n] * x[s][n], count += 1.0;
      REQUIRE(c.stretch_mean(g, j)[0] == Approx(sum / count).epsilon(1e-10));
    }
  }
}

TEST_CASE("First Sonine values: hard spheres and isotropic scattering", "[transport]") {
  // the collision laws of the models, as registry::model_traits gives them
  const auto law = [](const char* model, double vhs_exponent) {
    const registry::ModelTraits m = registry::model_traits(model, vhs_exponent);
    return analysis::CollisionLaw{m.exponent, m.isotropic_scattering};
  };
  const analysis::CollisionLaw hs = law("hs", 0.5), maxwell = law("maxwell", 0.5),
                               iso1 = law("vhs", 1.0), iso0 = law("vhs", 0.0);
  REQUIRE(hs.exponent == 1.0);
  REQUIRE(!hs.isotropic_scattering);
  REQUIRE(maxwell.exponent == 0.0);
  REQUIRE(maxwell.isotropic_scattering);
  REQUIRE(iso1.exponent == 1.0);
  // 3D hard spheres: eta* = 5/4, lambda* = 15/4 eta*, D* = 3/2 (Chapman & Cowling)
  const auto hs3 = analysis::first_sonine(hs, 3);
  REQUIRE(hs3[0] == Approx(1.25));
  REQUIRE(hs3[1] == Approx(15.0 / 4.0 * 1.25));
  REQUIRE(hs3[2] == Approx(1.5));
  // in 3D hard-sphere scattering is isotropic: vhs with a = 1 gives the same values
  const auto vhs3 = analysis::first_sonine(iso1, 3);
  for (int k = 0; k < 3; ++k) REQUIRE(vhs3[std::size_t(k)] == Approx(hs3[std::size_t(k)]));
  // elsewhere it is not: 4D eta*(hs) = 3/2, eta*(isotropic, a = 1) = 48/35
  REQUIRE(analysis::first_sonine(hs, 4)[0] == Approx(1.5));
  REQUIRE(analysis::first_sonine(iso1, 4)[0] == Approx(48.0 / 35.0));
  // Maxwell molecules: eta* = 2, D* = 2 in every D; vhs with a = 0 is the same model
  for (int d = 2; d <= 6; ++d) {
    const auto m = analysis::first_sonine(maxwell, d);
    REQUIRE(m[0] == Approx(2.0));
    REQUIRE(m[1] == Approx(2.0 * d * (d + 2.0) / (2.0 * (d - 1.0))));
    REQUIRE(m[2] == Approx(2.0));
    REQUIRE(analysis::first_sonine(iso0, d)[1] == Approx(m[1]));
  }
  REQUIRE_THROWS(analysis::first_sonine(hs, 1));
  // hard-sphere scattering has first Sonine values for its own rate exponent only
  REQUIRE_THROWS(analysis::first_sonine(analysis::CollisionLaw{0.5, false}, 3));
}

TEST_CASE("Fluxes: refused by the NTC scheme", "[transport]") {
  dsmc::Config cfg;
  cfg.n = 2000;
  cfg.seed = 4;
  cfg.scheme = dsmc::Scheme::ntc;
  cfg.dt = 0.1;
  dsmc::Engine<3, dsmc::HardSpheres> e(cfg);
  FluxCheck chk;
  REQUIRE_THROWS_AS(e.run_until(1.0, &chk, 0.5), InvalidInput);
}
