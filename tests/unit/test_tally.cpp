// The collision-level observer (hypergas/tally/): exact sums that do not depend on the order
// of additions, an engine's incrementally kept tally equal to one built from scratch, the
// same rows for every thread count, and the binned KS test bounded by the exact one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/analysis/moments.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/statistics.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/tally/exact_sum.hpp"
#include "hypergas/tally/tally.hpp"

using namespace hypergas;

TEST_CASE("ExactSum: the sum of rounded terms, whatever the order", "[tally]") {
  Rng r(7);
  std::vector<double> x;
  for (int i = 0; i < 5000; ++i) x.push_back(std::ldexp(r.uniform(), int(r.below(60))));
  x.push_back(0x1p100);  // beyond 2^96: the exponent table
  x.push_back(3.0 * 0x1p200);
  tally::ExactSum a, b;
  for (double v : x) a.add(v, +1);
  for (std::size_t i = x.size(); i-- > 0;) b.add(x[i], +1);
  REQUIRE(a == b);
  REQUIRE(a.value() == b.value());
  // removing every term in yet another order leaves exactly zero
  for (std::size_t i = 0; i < x.size(); i += 2) a.add(x[i], -1);
  for (std::size_t i = 1; i < x.size(); i += 2) a.add(x[i], -1);
  REQUIRE(a == tally::ExactSum{});
  REQUIRE(a.value() == 0.0);
  // rounding is to nearest, ties to even, symmetric in sign
  REQUIRE(tally::to_units_fast(2.5) == 2);
  REQUIRE(tally::to_units_fast(3.5) == 4);
  REQUIRE(tally::to_units_fast(-2.5) == -2);
  tally::ExactSum c;
  c.add(0x1p100, +1);
  c.add(1.0, +1);
  REQUIRE(c.value() == 0x1p100 + 1.0);
}

namespace {

/// Hands snapshots to a recorder without the engine's tally slot: it makes its own pass.
struct Strip final : Observer {
  analysis::MomentsRecorder* to = nullptr;
  void observe(const Snapshot& s) override {
    Snapshot c = s;
    c.tally = nullptr;
    to->observe(c);
  }
};

template <class Engine>
analysis::MomentsRecorder observe_fresh(Engine& e, analysis::MomentsRecorder rec) {
  Strip strip;
  strip.to = &rec;
  e.observe(strip);
  return rec;
}

/// The engine's tally after a run equals one made from its velocities, bit for bit; rows
/// from it equal the rows of a recorder that reads every particle.
template <int D, class Model, Features F>
void check_incremental(dsmc::Config cfg, int threads) {
  dsmc::Engine<D, Model, F> e(cfg);
  e.set_threads(threads, threads > 1 ? 2048 : 0);
  analysis::MomentsRecorder kept;
  e.observe(kept);  // installs the tally
  e.run_until(3.0, &kept, 0.5);
  REQUIRE(kept.passes() == 1);  // every later row came from the engine's tally
  // a fresh tally of the same layout from the velocities
  struct Grab final : Observer {
    const tally::Tally* t = nullptr;
    tally::Tally fresh;
    void observe(const Snapshot& s) override {
      t = s.tally->tally.get();
      fresh = tally::Tally(t->layout());
      fresh.add_snapshot(s, 0, s.n);
    }
  } grab;
  e.observe(grab);
  REQUIRE(grab.t != nullptr);
  REQUIRE(*grab.t == grab.fresh);
  // and the last row equals one from a full pass
  analysis::MomentsRecorder by_pass = observe_fresh(e, kept);
  const auto& a = kept.rows().back();
  const auto& b = by_pass.rows().back();
  REQUIRE(a.size() == b.size());
  for (std::size_t k = 2; k < a.size(); ++k)  // time and collisions per particle aside
    if (!std::isnan(a[k])) REQUIRE(a[k] == b[k]);
}

}  // namespace

TEST_CASE("Tally: kept by the collisions equals made from the velocities", "[tally]") {
  dsmc::Config cfg;
  cfg.n = 30000;
  cfg.seed = 11;
  cfg.init = InitialState::beams;
  SECTION("3D hard spheres, one thread") {
    check_incremental<3, dsmc::HardSpheres, Features{}>(cfg, 1);
  }
  SECTION("3D hard spheres, three threads (deferred and undone collisions)") {
    check_incremental<3, dsmc::HardSpheres, Features{}>(cfg, 3);
  }
  SECTION("6D Maxwell molecules") { check_incremental<6, dsmc::MaxwellMolecules, Features{}>(cfg, 2); }
  SECTION("1D two masses (species)") {
    cfg.init = InitialState::maxwell;
    cfg.initial.mass_ratio = 3.0;
    cfg.initial.fraction = 0.4;
    check_incremental<1, dsmc::HardSpheres, Features{.species = true}>(cfg, 1);
  }
  SECTION("2D two masses (species), two threads") {
    cfg.initial.mass_ratio = 0.25;
    cfg.initial.fraction = 0.5;
    check_incremental<2, dsmc::HardSpheres, Features{.species = true}>(cfg, 2);
  }
}

TEST_CASE("Tally: rows are the same for every thread count", "[tally]") {
  dsmc::Config cfg;
  cfg.n = 40000;
  cfg.seed = 5;
  cfg.init = InitialState::beams;
  std::vector<std::vector<std::vector<double>>> rows;
  for (int T : {1, 2, 3}) {
    dsmc::Engine<3, dsmc::HardSpheres> e(cfg);
    e.set_threads(T, T > 1 ? 4096 : 0);
    analysis::MomentsRecorder rec;
    rec.set_threads(T);
    e.run_until(2.0, &rec, 0.25);
    rows.push_back(rec.rows());
  }
  REQUIRE(rows[0] == rows[1]);
  REQUIRE(rows[0] == rows[2]);
}

TEST_CASE("Tally: moments agree with compensated double sums", "[tally]") {
  // The fixed-point sums differ from accurate double sums by their rounding, ~2^-41 of a
  // term per particle: far below 1e-12 relative for these moments (measured: ~1e-15).
  dsmc::Config cfg;
  cfg.n = 20000;
  cfg.seed = 3;
  dsmc::Engine<4, dsmc::HardSpheres> e(cfg);
  e.run_until(1.0);
  analysis::MomentsRecorder rec;
  e.observe(rec);
  struct Keep final : Observer {
    analysis::Moments m;
    void observe(const Snapshot& s) override { m = analysis::compute_moments(s); }
  } keep;
  e.observe(keep);
  const auto col = [&](const char* c) { return rec.column(c).back(); };
  REQUIRE(col("m2") == Approx(keep.m.m2.value).epsilon(1e-12));
  REQUIRE(col("m4") == Approx(keep.m.m4.value).epsilon(1e-12));
  REQUIRE(col("m6") == Approx(keep.m.m6.value).epsilon(1e-12));
  REQUIRE(col("kurtosis_x") == Approx(keep.m.kurtosis_x.value).epsilon(1e-12));
  REQUIRE(col("m6_err") == Approx(keep.m.m6.error).epsilon(1e-9));
  REQUIRE(col("kurtosis_x_err") == Approx(keep.m.kurtosis_x.error).epsilon(1e-9));
  REQUIRE(col("kT") == Approx(keep.m.kT).epsilon(1e-13));
}

TEST_CASE("Binned KS: between the exact statistic and it minus a bin's probability",
          "[tally]") {
  // Exact bounds (docs in statistics.hpp), checked on MB samples and on a shifted one.
  const analysis::MaxwellReference ref{analysis::Quantity::speed, 3, 1.0, 1.0};
  for (double scale : {1.0, 1.02}) {
    Rng r(21);
    std::vector<double> x;
    for (int i = 0; i < 20000; ++i) {
      double vv = 0.0;
      for (int d = 0; d < 3; ++d) {
        const double c = scale * r.normal();
        vv += c * c;
      }
      x.push_back(std::sqrt(vv));
    }
    const std::size_t bins = 4000;
    const double hi = 7.0, h = hi / bins;
    std::vector<std::int64_t> counts(bins + 2, 0);
    for (double v : x) {
      const auto b = static_cast<std::size_t>(v / h);
      ++counts[std::min(b, bins) + 1];
    }
    std::vector<double> cdf(bins + 1);
    double pmax = 0.0;
    for (std::size_t k = 0; k <= bins; ++k) {
      cdf[k] = ref.cdf(h * double(k));
      if (k > 0) pmax = std::max(pmax, cdf[k] - cdf[k - 1]);
    }
    pmax = std::max(pmax, 1.0 - cdf[bins]);
    const auto binned = analysis::ks_test_binned(counts.data(), cdf.data(), bins);
    const auto exact = analysis::ks_test(x, ref);
    REQUIRE(binned.statistic <= exact.statistic + 1e-15);
    REQUIRE(binned.statistic >= exact.statistic - pmax - 1e-15);
    REQUIRE(binned.p_value >= exact.p_value);
  }
}

TEST_CASE("Tally: dropped where rows are sparse, with the same rows", "[tally]") {
  // rows 5 time units apart hold 2.5 n collisions, above tally_limit * n: after the second
  // row the recorder takes the tally out of the engine and makes each row by a pass
  dsmc::Config cfg;
  cfg.n = 4000;
  cfg.seed = 21;
  cfg.init = InitialState::beams;
  dsmc::Engine<3, dsmc::HardSpheres> a(cfg), b(cfg);
  analysis::MomentsRecorder ra, rb;
  Strip strip;
  strip.to = &rb;
  struct Probe final : Observer {  // whether the engine keeps a tally after each row
    analysis::MomentsRecorder* to;
    std::vector<bool> kept;
    bool had = false;
    void observe(const Snapshot& s) override {
      to->observe(s);
      had = s.tally->tally != nullptr;
    }
    void request(tally::Requests& r) override {
      to->request(r);
      kept.push_back(r.replace_tally ? r.tally != nullptr : had);
    }
  } probe;
  probe.to = &ra;
  a.run_until(20.0, &probe, 5.0);
  b.run_until(20.0, &strip, 5.0);
  REQUIRE(probe.kept == std::vector<bool>{true, false, false, false, false});
  REQUIRE(ra.rows() == rb.rows());
  // dense rows keep it
  dsmc::Engine<3, dsmc::HardSpheres> c(cfg);
  analysis::MomentsRecorder rc;
  probe.to = &rc;
  probe.kept.clear();
  c.run_until(1.0, &probe, 0.25);
  REQUIRE(probe.kept == std::vector<bool>(5, true));
}
