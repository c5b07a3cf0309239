// MomentsRecorder's streaming passes (analysis/moments_recorder.hpp), compensated sums
// (analysis/sample.hpp), the KS subsample (SequentialSample, analysis/statistics.hpp) and
// checkpoints of the recorder (hypergas/checkpoint.hpp).
//
// - Up to the KS cap the recorder's rows and histograms equal, bit for bit, those of the
//   copy-and-sort computation it replaced (values(), make_histogram on the copy, ks_test
//   sorting a copy, plain sums); above the cap they equal it to round-off, except the KS
//   p-value, which then comes from a subsample.
// - Compensated moments of 1e7 values spanning 12 decades agree with a long double
//   reference to a few eps.
// - Above the cap the KS test still rejects unrelaxed states (p < 1e-6) and accepts MB
//   samples (p > 1e-4: under MB, with kT from the whole snapshot, p is close to uniform, so
//   each such check fails for a fraction ~1e-4 of seeds; 2 checks, ~2e-4 in all).
// - A recorder saved and restored mid-run continues bit for bit as the original.
// - Above the cap the passes run over fixed chunks: every thread count gives the same rows
//   and histograms, bit for bit.
#include <catch2/catch.hpp>

#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/moments.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/analysis/statistics.hpp"
#include "hypergas/checkpoint.hpp"
#include "hypergas/error.hpp"
#include "test_analysis_support.hpp"

using namespace hypergas;
using namespace hypergas::analysis;
namespace fs = std::filesystem;

namespace {

// Bitwise equality of two rows (NaN equals NaN of the same bits).
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// What MomentsRecorder computed per snapshot before its streaming passes: copies of the
// speeds, histograms filled from the copies, KS on a sorted copy, plain sums.
struct OldStyle {
  std::vector<double> row;
  std::vector<Histogram> hists;
  std::vector<MaxwellReference> refs;
};

OldStyle old_style(const Snapshot& s, std::size_t bins) {
  constexpr Summation plain = Summation::plain;
  const int ns = s.species ? s.n_species : 1;
  const Moments m = compute_moments(s, -1, plain);
  const MaxwellReference ref = reference(s, Quantity::speed, -1, plain);
  const std::vector<double> speeds = values(s, Quantity::speed, -1, plain);
  Histogram h = make_histogram(speeds, ref, bins);
  OldStyle o;
  o.row = {s.time,
           s.collisions_per_particle,
           m.m2.value,
           m.m4.value,
           m.kurtosis_x.value,
           m.m6.value,
           m.m2.error,
           m.m4.error,
           m.m6.error,
           m.kurtosis_x.error,
           m.m4_ratio.value,
           m.m4_ratio.error,
           m.kT,
           l1_distance(h, ref),
           kl_divergence(h, ref),
           ks_test(speeds, ref).p_value,
           chi_square_test(h, ref, 1).p_value};
  o.hists.push_back(h);
  o.refs.push_back(ref);
  if (ns > 1)
    for (int k = 0; k < ns; ++k) {
      const bool present = count(s, k) > 0;
      o.row.push_back(present ? temperature(s, k, plain) : NAN);
      const MaxwellReference rk = present ? reference(s, Quantity::speed, k, plain) : ref;
      o.hists.push_back(make_histogram(
          present ? values(s, Quantity::speed, k) : std::vector<double>{}, rk, bins));
      o.refs.push_back(rk);
    }
  // the trailing columns: the cumulants a2, a3 from the plain moments, T, real_time
  const double d = s.dim, m2 = m.m2.value;
  const double a2 = d / (d + 2.0) * m.m4.value / (m2 * m2) - 1.0;
  o.row.push_back(a2);
  o.row.push_back(1.0 + 3.0 * a2 - d * d * m.m6.value / ((d + 2.0) * (d + 4.0) * m2 * m2 * m2));
  o.row.push_back(m.kT * std::exp(2.0 * s.log_velocity_scale));
  o.row.push_back(std::isnan(s.real_time) ? s.time : s.real_time);
  return o;
}

// A two-species gas (species 1 of mass 3, ~40% of the particles) in D dimensions, relaxed
// (MB at kT = 1.3) or not (every speed 1, directions along the axes).
test::OwnedState mixture(int dim, std::size_t n, Rng& rng, bool relaxed) {
  test::OwnedState st(dim, n);
  st.species.resize(n);
  st.species_inv_mass = {1.0, 1.0 / 3.0};
  for (std::size_t i = 0; i < n; ++i) {
    st.species[i] = rng.uniform() < 0.4 ? 1 : 0;
    const double inv_m = st.species_inv_mass[st.species[i]];
    for (int k = 0; k < dim; ++k)
      st.velocity(i)[k] =
          relaxed ? std::sqrt(1.3 * inv_m) * rng.normal() : (k == int(i % dim) ? 1.0 : 0.0);
  }
  return st;
}

}  // namespace

TEST_CASE("Running sums: the plain part is the plain sum, the compensated one exact",
          "[analysis]") {
  // 1 + 1e-16 + ... : the plain sum never moves from 1, the compensated one sees every term.
  RunningSum r;
  double plain = 0.0;
  r.add(1.0);
  plain += 1.0;
  for (int i = 0; i < 1000; ++i) {
    r.add(1e-16);
    plain += 1e-16;
  }
  CHECK(r.plain() == plain);
  CHECK(r.plain() == 1.0);
  CHECK(r.compensated() == Approx(1.0 + 1e-13).epsilon(1e-15));
  CHECK(r.value(Summation::plain) == r.plain());
  // Cancellation: 1e20 + 1 - 1e20 is 1, not 0.
  RunningSum c;
  c.add(1e20);
  c.add(1.0);
  c.add(-1e20);
  CHECK(c.plain() == 0.0);
  CHECK(c.compensated() == 1.0);
}

TEST_CASE("Tally recorder equals the copy-and-sort computation to round-off",
          "[analysis]") {
  // The rows come from exact fixed-point sums (tally.hpp), the copies from plain double
  // sums: they agree to the plain sums' rounding, ~sqrt(n) eps; errors are differences of
  // nearly equal means and lose their common digits. The histograms count the same values.
  constexpr std::size_t bins = 30;
  Rng rng(71);
  for (int dim : {1, 2, 3, 5}) {
    for (bool species : {false, true}) {
      for (bool relaxed : {true, false}) {
        INFO("D = " << dim << (species ? ", two species" : ", one species")
                    << (relaxed ? ", MB" : ", unrelaxed"));
        constexpr std::size_t n = 3000;
        test::OwnedState st(dim, n);
        if (species) {
          st = mixture(dim, n, rng, relaxed);
        } else if (relaxed) {
          test::fill_maxwell(st, rng, 0.7);
        } else {
          for (std::size_t i = 0; i < n; ++i)
            for (int k = 0; k < dim; ++k) st.velocity(i)[k] = rng.uniform() - 0.5;
        }
        Snapshot s = st.snapshot();
        s.time = 1.25;
        s.collisions_per_particle = 3.5;
        const OldStyle old = old_style(s, bins);
        for (std::size_t cap : {n, std::size_t{0}, n / 4}) {
          INFO("KS sample " << cap);
          MomentsRecorder rec(bins, cap);
          rec.observe(s);
          const auto& r = rec.rows().back();
          const auto ks = static_cast<std::size_t>(
              std::find(rec.columns().begin(), rec.columns().end(), "ks_p_speed") -
              rec.columns().begin());
          for (std::size_t c = 0; c < r.size(); ++c) {
            INFO("column " << rec.columns()[c]);
            if (std::isnan(old.row[c])) continue;
            if (c == ks && cap != n) {  // binned or subsampled: another statistic
              CHECK(r[c] >= 0.0);
              CHECK(r[c] <= 1.0);
              continue;
            }
            if (c == ks && old.row[c] < 1e-12) {  // far in the tail p is not round-off-stable
              CHECK(r[c] < 1e-12);
              continue;
            }
            // errors and the cumulants a2, a3 are differences of nearly equal numbers
            const bool err = rec.columns()[c].ends_with("_err") || rec.columns()[c] == "a2" ||
                             rec.columns()[c] == "a3";
            CHECK(r[c] == Approx(old.row[c]).epsilon(err ? 1e-9 : 1e-12).margin(1e-300));
          }
          for (std::size_t k = 0; k < old.hists.size(); ++k) {
            const Histogram& h = rec.last_histogram(static_cast<int>(k) - 1);
            CHECK(h.underflow() == old.hists[k].underflow());
            CHECK(h.overflow() == old.hists[k].overflow());
            for (std::size_t b = 0; b < bins; ++b) CHECK(h.count(b) == old.hists[k].count(b));
          }
        }
      }
    }
  }
}

TEST_CASE("Compensated moments of 1e7 mixed-magnitude values: error of a few eps", "[analysis]") {
  // D = 1, stride 1, two species (masses 1 and 4): |v| = 10^u, u uniform on [-3, 3], random
  // sign, so v^2 spans 12 decades and v^6 36. Reference: the same sums in long double (64-bit
  // significand), themselves compensated, so that their own error (~1e-19) is negligible.
  constexpr std::size_t n = 10'000'000;
  std::vector<double> v(n);
  std::vector<std::uint8_t> sp(n);
  const double inv_mass[2] = {1.0, 0.25};
  Rng rng(72);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = (rng.uniform() < 0.5 ? -1.0 : 1.0) * std::pow(10.0, 6.0 * rng.uniform() - 3.0);
    sp[i] = rng.uniform() < 0.3;
  }
  Snapshot s;
  s.dim = 1;
  s.n = n;
  s.stride = 1;
  s.velocities = v.data();
  s.species = sp.data();
  s.species_inv_mass = inv_mass;
  s.n_species = 2;

  struct LongSum {  // Kahan–Babuška in long double
    long double s = 0, c = 0;
    void add(long double x) {
      const long double t = s + x;
      c += std::fabs(s) >= std::fabs(x) ? (s - t) + x : (x - t) + s;
      s = t;
    }
    long double get() const { return s + c; }
  };
  LongSum mass, s2, s4, s6, w4, twice_e;
  for (std::size_t i = 0; i < n; ++i) mass.add(1.0L / inv_mass[sp[i]]);
  const long double m_mean = mass.get() / n;
  for (std::size_t i = 0; i < n; ++i) {
    const auto vi = static_cast<long double>(v[i]);
    const long double vv = vi * vi, m = 1.0L / inv_mass[sp[i]];
    const long double f = m / m_mean;
    s2.add(vv);
    s4.add(vv * vv);
    s6.add(vv * vv * vv);
    w4.add(vv * vv * f * f);  // D = 1: w_x^4 = w^4
    twice_e.add(m * vv);
  }
  // D = 1: kT = <m v^2>, and <w_x^2> = <v^2 m / m_mean> = kT / m_mean.
  const long double kT = twice_e.get() / n;
  const long double b = kT / m_mean;
  const long double ref_m2 = s2.get() / n, ref_m4 = s4.get() / n, ref_m6 = s6.get() / n;
  const long double ref_kurt = (w4.get() / n) / (b * b);
  const long double ref_ratio = (w4.get() / n) / (3.0L * (kT / m_mean) * (kT / m_mean));

  const auto rel = [](double x, long double ref) {
    return static_cast<double>(std::fabs((static_cast<long double>(x) - ref) / ref));
  };
  const Moments c = compute_moments(s, -1, Summation::compensated);
  const Moments p = compute_moments(s, -1, Summation::plain);
  INFO("relative errors, compensated / plain: m2 "
       << rel(c.m2.value, ref_m2) << " / " << rel(p.m2.value, ref_m2) << ", m6 "
       << rel(c.m6.value, ref_m6) << " / " << rel(p.m6.value, ref_m6) << ", kT " << rel(c.kT, kT)
       << " / " << rel(p.kT, kT));
  constexpr double eps = 0x1p-53;
  // A mean is one compensated sum (error ~eps) divided by n (eps): 4 eps is ample.
  CHECK(rel(c.m2.value, ref_m2) < 4 * eps);
  CHECK(rel(c.m4.value, ref_m4) < 4 * eps);
  CHECK(rel(c.m6.value, ref_m6) < 4 * eps);
  CHECK(rel(c.kT, kT) < 4 * eps);
  // Ratios of such means, and m_mean in the weights: a few more roundings.
  CHECK(rel(c.kurtosis_x.value, ref_kurt) < 32 * eps);
  CHECK(rel(c.m4_ratio.value, ref_ratio) < 32 * eps);
  // The plain sums are no better (typically ~sqrt(n) eps worse).
  CHECK(rel(c.m2.value, ref_m2) <= rel(p.m2.value, ref_m2) + 2 * eps);
  // The recorder's exact fixed-point sums: each term rounded to ~2^-41 of a typical one.
  MomentsRecorder rec(50);
  rec.observe(s);
  CHECK(rel(rec.column("m2")[0], ref_m2) < 1e-13);
  CHECK(rel(rec.column("m6")[0], ref_m6) < 1e-13);
  CHECK(rel(rec.column("kT")[0], kT) < 1e-13);
}

TEST_CASE("Selection sampling takes exactly k of n, every index and pair as often as due",
          "[analysis]") {
  // n = 20, k = 7, 200000 draws: index i is taken Binomial(200000, 7/20) times (sd 213);
  // pair (i, j) Binomial(200000, 42/380) (sd 140). Checked within 5 sd: p = 5.7e-7 per
  // check, 24 checks, false-failure probability < 1.4e-5.
  constexpr std::uint64_t n = 20, k = 7;
  constexpr int draws = 200000;
  std::vector<double> hits(n, 0.0);
  double pair_01 = 0, pair_5_19 = 0, pair_2_13 = 0, pair_0_19 = 0;
  Rng root(73);
  for (int d = 0; d < draws; ++d) {
    SequentialSample pick(n, k, root.split(static_cast<std::uint64_t>(d)));
    std::vector<bool> in(n);
    std::uint64_t taken = 0;
    for (std::uint64_t i = 0; i < n; ++i)
      if (pick.take()) {
        in[i] = true;
        hits[i] += 1;
        ++taken;
      }
    REQUIRE(taken == k);
    REQUIRE(!pick.take());  // past the end
    pair_01 += in[0] && in[1];
    pair_5_19 += in[5] && in[19];
    pair_2_13 += in[2] && in[13];
    pair_0_19 += in[0] && in[19];
  }
  const double p1 = double(k) / n, p2 = double(k * (k - 1)) / double(n * (n - 1));
  const double sd1 = std::sqrt(draws * p1 * (1 - p1)), sd2 = std::sqrt(draws * p2 * (1 - p2));
  for (std::uint64_t i = 0; i < n; ++i) CHECK(std::abs(hits[i] - draws * p1) < 5 * sd1);
  for (double c : {pair_01, pair_5_19, pair_2_13, pair_0_19})
    CHECK(std::abs(c - draws * p2) < 5 * sd2);
  // k >= n takes everything; k = 0 nothing.
  SequentialSample all(5, 9, Rng(1));
  SequentialSample none(5, 0, Rng(1));
  for (int i = 0; i < 5; ++i) {
    CHECK(all.take());
    CHECK(!none.take());
  }
}

TEST_CASE("Above the KS cap: unrelaxed states still fail, MB passes, reproducibly", "[analysis]") {
  const auto ks_p = [](const MomentsRecorder& r) { return r.column("ks_p_speed").back(); };
  SECTION("default (binned on all speeds) and n = 1.2e6") {
    constexpr std::size_t n = 1'200'000;
    test::OwnedState st(3, n);
    Rng rng(74);
    MomentsRecorder rec;
    REQUIRE(rec.ks_cap() == 0);
    test::fill_maxwell(st, rng, 1.0);
    rec.observe(st.snapshot());
    CHECK(ks_p(rec) > 1e-4);
    // Every speed 1, directions uniform (the DSMC "delta" start).
    for (std::size_t i = 0; i < n; ++i) {
      double* v = st.velocity(i);
      double vv = 0;
      for (int k = 0; k < 3; ++k) {
        v[k] = rng.normal();
        vv += v[k] * v[k];
      }
      for (int k = 0; k < 3; ++k) v[k] /= std::sqrt(vv);
    }
    rec.observe(st.snapshot());
    CHECK(ks_p(rec) < 1e-6);
  }
  SECTION("small cap: two warm beams fail, a mixture at MB passes") {
    constexpr std::size_t n = 40000, cap = 2000;
    Rng rng(75);
    // Two beams along x at +-1 with thermal spread kT_beam = 0.05 (D = 2): the speeds
    // cluster around 1, far from MB at the total kT.
    test::OwnedState beams(2, n);
    for (std::size_t i = 0; i < n; ++i) {
      beams.velocity(i)[0] = (i % 2 ? 1.0 : -1.0) + std::sqrt(0.05) * rng.normal();
      beams.velocity(i)[1] = std::sqrt(0.05) * rng.normal();
    }
    MomentsRecorder rec(50, cap);
    rec.observe(beams.snapshot());
    CHECK(ks_p(rec) < 1e-6);
    const test::OwnedState mix = mixture(2, n, rng, true);
    MomentsRecorder rec_mix(50, cap);
    rec_mix.observe(mix.snapshot());
    CHECK(ks_p(rec_mix) > 1e-4);
    // Reproducible: the same seed draws the same subsample; another seed another one. The
    // subsample of snapshot j does not depend on what earlier snapshots were.
    MomentsRecorder again(50, cap), other(50, cap, 12345), later(50, cap);
    again.observe(mix.snapshot());
    other.observe(mix.snapshot());
    later.observe(mixture(2, n / 2, rng, true).snapshot());  // another size first
    later.observe(mix.snapshot());
    MomentsRecorder second(50, cap);
    second.observe(mix.snapshot());
    second.observe(mix.snapshot());
    CHECK(ks_p(again) == ks_p(rec_mix));
    CHECK(ks_p(other) != ks_p(rec_mix));
    CHECK(ks_p(later) == ks_p(second));
    CHECK(ks_p(second) != ks_p(rec_mix));  // snapshot 1 draws another subsample than 0
  }
  CHECK_THROWS_AS(MomentsRecorder(0, 100), InvalidInput);  // no bin (ks_sample 0 is the binned test)
}

TEST_CASE("Above the KS cap the rows are the same for every thread count", "[analysis]") {
  // 300000 particles in chunks of 65536: five chunks, the last one short; a mixture, so
  // that the species histograms and temperatures are reduced across threads too.
  constexpr std::size_t n = 300000, cap = 5000;
  Rng rng(91);
  const test::OwnedState mix = mixture(3, n, rng, true);
  std::vector<std::vector<double>> rows;
  std::vector<std::vector<double>> counts;
  for (int threads : {1, 2, 3, 5}) {
    MomentsRecorder rec(40, cap, 4321);
    rec.set_threads(threads);
    REQUIRE(rec.threads() == threads);
    rec.observe(mix.snapshot());
    rec.observe(mix.snapshot());
    for (const auto& row : rec.rows()) rows.push_back(row);
    std::vector<double> c;
    for (int sp = -1; sp < 2; ++sp)
      for (std::size_t b = 0; b < 40; ++b) c.push_back(rec.last_histogram(sp).count(b));
    counts.push_back(c);
  }
  for (std::size_t k = 2; k < rows.size(); ++k) CHECK(rows[k] == rows[k % 2]);
  for (const auto& c : counts) CHECK(c == counts[0]);
  {
    MomentsRecorder rec(40, cap, 4321);
    rec.observe(mix.snapshot());
    CHECK(rec.column("ks_p_speed").back() > 1e-4);  // MB: the stratified subsample accepts it
  }
  MomentsRecorder bad(40, cap);
  CHECK_THROWS_AS(bad.set_threads(0), InvalidInput);
}

TEST_CASE("A recorder saved and restored continues exactly as the original", "[analysis]") {
  // Mixture in D = 2 with the KS cap below n, so that the restored subsample stream matters.
  constexpr std::size_t n = 5000, cap = 1500, bins = 24;
  Rng rng(76);
  std::vector<test::OwnedState> states;
  for (int j = 0; j < 6; ++j) states.push_back(mixture(2, n, rng, j % 3 != 0));
  const auto snap = [&](int j) {
    Snapshot s = states[static_cast<std::size_t>(j)].snapshot();
    s.time = 0.5 * j;
    s.collisions_per_particle = 0.25 * j;
    return s;
  };
  MomentsRecorder original(bins, cap, 987);
  for (int j = 0; j < 3; ++j) original.observe(snap(j));

  test::TempDir dir;
  const std::string ckpt = (dir.path / "recorder.ckpt").string();
  {
    checkpoint::Writer w(ckpt);
    original.io(w);
    w.commit();
  }
  MomentsRecorder restored(7, 3, 1);  // other parameters: the checkpoint replaces them
  {
    checkpoint::Reader r(ckpt);
    restored.io(r);
    r.finish();
  }
  REQUIRE(restored.ks_cap() == cap);
  REQUIRE(restored.columns() == original.columns());
  REQUIRE(restored.rows().size() == 3);
  for (int j = 3; j < 6; ++j) {
    original.observe(snap(j));
    restored.observe(snap(j));
  }
  REQUIRE(restored.rows().size() == original.rows().size());
  for (std::size_t j = 0; j < original.rows().size(); ++j) {
    INFO("row " << j);
    CHECK(same_bits(restored.rows()[j], original.rows()[j]));
  }
  original.write_moments_csv((dir.path / "ma.csv").string());
  restored.write_moments_csv((dir.path / "mb.csv").string());
  CHECK(test::read_text(dir.path / "ma.csv") == test::read_text(dir.path / "mb.csv"));
  for (int sp = -1; sp < 2; ++sp) {
    INFO("species " << sp);
    original.write_speed_histogram_csv((dir.path / "ha.csv").string(), sp);
    restored.write_speed_histogram_csv((dir.path / "hb.csv").string(), sp);
    CHECK(test::read_text(dir.path / "ha.csv") == test::read_text(dir.path / "hb.csv"));
  }
  // A fresh recorder round-trips too (nothing observed yet), and the restored one then
  // records as a new one would.
  {
    checkpoint::Writer w(ckpt);
    MomentsRecorder fresh(bins, cap, 987);
    fresh.io(w);
    w.commit();
  }
  MomentsRecorder from_fresh;
  {
    checkpoint::Reader r(ckpt);
    from_fresh.io(r);
    r.finish();
  }
  MomentsRecorder direct(bins, cap, 987);
  from_fresh.observe(snap(4));
  direct.observe(snap(4));
  CHECK(same_bits(from_fresh.rows()[0], direct.rows()[0]));
}

TEST_CASE("Histogram checkpoints restore edges, counts and tails exactly", "[analysis]") {
  Histogram h(0.1, 2.9, 13);
  Rng rng(77);
  for (int i = 0; i < 1000; ++i) h.add(4.0 * rng.uniform() - 0.5);
  test::TempDir dir;
  const std::string ckpt = (dir.path / "h.ckpt").string();
  {
    checkpoint::Writer w(ckpt);
    h.io(w);
    w.commit();
  }
  Histogram g;
  CHECK(g.bins() == 1);
  {
    checkpoint::Reader r(ckpt);
    g.io(r);
    r.finish();
  }
  REQUIRE(g.bins() == h.bins());
  for (std::size_t i = 0; i < h.bins(); ++i) {
    CHECK(g.lower(i) == h.lower(i));
    CHECK(g.upper(i) == h.upper(i));
    CHECK(g.count(i) == h.count(i));
  }
  CHECK(g.underflow() == h.underflow());
  CHECK(g.overflow() == h.overflow());
  CHECK(g.total() == 1000.0);
  // Both keep counting alike.
  for (double x : {-1.0, 0.1, 1.0, 2.9, 5.0}) {
    h.add(x);
    g.add(x);
  }
  for (std::size_t i = 0; i < h.bins(); ++i) CHECK(g.count(i) == h.count(i));
  CHECK(g.total() == h.total());
}
