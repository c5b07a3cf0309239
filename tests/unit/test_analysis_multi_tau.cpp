// Multiple-tau correlator (analysis/multi_tau.hpp) and the VacfRecorder built on it.
//
// 1. Definition, to round-off (deterministic): level 0 (lags < p) equals vacf_direct /
//    msd_direct of the whole series; level l equals vacf_direct of the series of m^l-frame
//    block means, and msd_direct of the series decimated to every m^l-th frame (the last of
//    each block), at block lags p/m .. p-1; origins and the lag grid are as documented.
// 2. Statistics against an exactly known process. AR(1) series x(t+1) = rho x(t) +
//    sqrt(1 - rho^2) z (stationary Gaussian, covariance rho^|s|), 400 particles x 3
//    components, 4096 frames, rho = exp(-1/200). The estimator's expectation at lag j m^l
//    is 3 g_l(j), g_l the covariance of the block means: the exact correlation smoothed
//    over a block, larger by a factor (sinh(B/400) / (B sinh(1/400)))^2 ~ 1 + (B^2 - 1) /
//    (12 * 200^2) for blocks of B frames (15 % at the largest lags here). Its variance is
//    exact by Isserlis' theorem: for T' origins, per component, Var = (1/T'^2)
//    sum_{|s|<T'} (T' - |s|) [g(s)^2 + g(s+j) g(s-j)], times 3/400 for the sum of 3
//    components averaged over 400 particles. The test allows 5.5 sd at each of the 73 lags:
//    if the estimates are normal (each is a mean over 1200 independent series)
//    P(|Z| > 5.5) = 3.8e-8 per lag, < 3e-6 in all (union bound).
// 3. MSD. Ballistic motion x = x0 + v t with integer x0, v, t: every displacement and sum is
//    an exact integer below 2^53, so the MSD equals <|v|^2> lag^2 up to the final division
//    (1e-14 relative) at every lag, the coarse ones included (decimation keeps exact
//    positions). A unit random walk: expectation D lag at every lag (unbiased), variance
//    exact, Cov(d_a^2, d_b^2) = 2 (lag - B |a - b|)_+^2 for origins B frames apart; 5.5 sd
//    allowed. The estimates are means of 1200 independent chi-square-like terms; with the
//    skew of a chi-square of >= 1200 degrees of freedom (Wilson–Hilferty) the one-sided
//    tail beyond 5.5 sd is < 2e-7 per lag, < 2e-5 over the 73 lags.
// 4. Memory: bytes() is the same after 1e3 and 1e5 frames once every level is in use, and
//    equals the documented bound.
// 5. Checkpoint: a recorder saved with checkpoint::Writer and restored with Reader, then fed
//    the same frames as the original, gives bit-identical lags, origins, VACF, MSD and
//    Green–Kubo value; a file of another layout is refused.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "hypergas/analysis/multi_tau.hpp"
#include "hypergas/analysis/vacf.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "hypergas/checkpoint.hpp"
#include "hypergas/error.hpp"
#include "hypergas/rng.hpp"
#include "support/correlation.hpp"
#include "test_analysis_support.hpp"

using namespace hypergas;
using namespace hypergas::analysis;
using test_support::msd_direct;
using test_support::vacf_direct;
using Kind = MultiTauCorrelator::Kind;

namespace {
std::size_t ipow(std::size_t m, std::size_t l) {
  std::size_t r = 1;
  while (l-- > 0) r *= m;
  return r;
}

// Feeds `frames` frames of `w` values each (frame f at data[f * w]) to c.
void feed(MultiTauCorrelator& c, const std::vector<double>& data, std::size_t w) {
  for (std::size_t f = 0; f < data.size() / w; ++f) c.add(data.data() + f * w, c.dim());
}

// Means of consecutive blocks of B frames (incomplete last block dropped).
std::vector<double> block_means(const std::vector<double>& x, std::size_t w, std::size_t B) {
  const std::size_t blocks = x.size() / w / B;
  std::vector<double> out(blocks * w, 0.0);
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t i = 0; i < B; ++i)
      for (std::size_t k = 0; k < w; ++k) out[b * w + k] += x[(b * B + i) * w + k];
  for (double& v : out) v /= static_cast<double>(B);
  return out;
}

// Frames B-1, 2B-1, ...: the last frame of each complete block.
std::vector<double> decimate(const std::vector<double>& x, std::size_t w, std::size_t B) {
  const std::size_t blocks = x.size() / w / B;
  std::vector<double> out(blocks * w);
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t k = 0; k < w; ++k) out[b * w + k] = x[((b + 1) * B - 1) * w + k];
  return out;
}

// Looks up the value at `lag` in a curve; REQUIREs that it is there.
std::size_t index_of(const MultiTauCurve& c, std::size_t lag) {
  for (std::size_t i = 0; i < c.lag.size(); ++i)
    if (c.lag[i] == lag) return i;
  FAIL("lag " << lag << " missing");
  return 0;
}

// n particles in `dim` dimensions, stride dim + 1 (a padding slot), velocities and positions.
struct Frame {
  int dim;
  std::size_t n;
  std::vector<double> v, x;
  Frame(int d, std::size_t np)
      : dim(d), n(np), v(np * static_cast<std::size_t>(d + 1), -7.0), x(v.size(), -7.0) {}
  Snapshot snapshot(double time, bool positions) const {
    Snapshot s;
    s.dim = dim;
    s.n = n;
    s.stride = dim + 1;
    s.time = time;
    s.velocities = v.data();
    s.positions = positions ? x.data() : nullptr;
    return s;
  }
};
}  // namespace

TEST_CASE("Multiple-tau: exact level 0, block means and decimation on coarser levels",
          "[analysis]") {
  Rng rng(71);
  const std::size_t n = 7;
  const int dim = 3;
  const std::size_t w = n * dim;
  const std::vector<std::array<std::size_t, 3>> cases = {
      {16, 2, 1000}, {8, 4, 777}, {6, 3, 500}, {16, 2, 9}};  // p, m, frames
  for (const auto& [p, m, frames] : cases) {
    INFO("p " << p << " m " << m << " frames " << frames);
    // Correlated values with a non-zero mean; positions a drifting random walk.
    std::vector<double> v(frames * w), x(frames * w);
    for (std::size_t k = 0; k < w; ++k) {
      v[k] = rng.normal() + 0.5;
      x[k] = 20.0 * rng.normal();
    }
    for (std::size_t f = 1; f < frames; ++f)
      for (std::size_t k = 0; k < w; ++k) {
        v[f * w + k] = 0.5 + 0.8 * (v[(f - 1) * w + k] - 0.5) + 0.6 * rng.normal();
        x[f * w + k] = x[(f - 1) * w + k] + v[f * w + k];
      }
    MultiTauCorrelator cv(Kind::correlation, n, dim, p, m), cx(Kind::displacement, n, dim, p, m);
    feed(cv, v, w);
    feed(cx, x, w);
    CHECK(cv.samples() == frames);
    const MultiTauCurve rv = cv.curve(frames), rx = cx.curve(frames);
    REQUIRE(rv.lag == rx.lag);
    CHECK(rv.origins == rx.origins);

    // The lag grid: 0..p-1, then j m^l for j = p/m..p-1, wherever there is an origin.
    std::vector<std::size_t> grid;
    for (std::size_t l = 0; ipow(m, l) <= frames; ++l)
      for (std::size_t j = l == 0 ? 0 : p / m; j < p; ++j)
        if (j < frames / ipow(m, l)) grid.push_back(j * ipow(m, l));
    CHECK(rv.lag == grid);

    const std::size_t l0 = std::min(p - 1, frames - 1);
    const auto ref_v = vacf_direct(v, frames, n, dim, l0);
    const auto ref_x = msd_direct(x, frames, n, dim, l0);
    for (std::size_t j = 0; j <= l0; ++j) {
      const std::size_t i = index_of(rv, j);
      CHECK(rv.origins[i] == frames - j);
      CHECK(std::abs(rv.value[i] - ref_v[j]) <= 1e-12 * ref_v[0]);
      CHECK(std::abs(rx.value[i] - ref_x[j]) <= 1e-12 * ref_x[l0]);
    }
    for (std::size_t l = 1; p / m < frames / ipow(m, l); ++l) {
      const std::size_t B = ipow(m, l), blocks = frames / B, jmax = std::min(p - 1, blocks - 1);
      INFO("level " << l);
      const auto ref_vb = vacf_direct(block_means(v, w, B), blocks, n, dim, jmax);
      const auto ref_xb = msd_direct(decimate(x, w, B), blocks, n, dim, jmax);
      for (std::size_t j = p / m; j <= jmax; ++j) {
        const std::size_t i = index_of(rv, j * B);
        CHECK(rv.origins[i] == blocks - j);
        CHECK(std::abs(rv.value[i] - ref_vb[j]) <= 1e-12 * ref_vb[0]);
        CHECK(std::abs(rx.value[i] - ref_xb[j]) <= 1e-12 * ref_xb[jmax]);
      }
    }
  }
  // A level cap ends the grid at (p-1) m^(levels-1).
  MultiTauCorrelator capped(Kind::correlation, 2, 1, 4, 2, 3);
  CHECK(capped.max_lag() == 12);
  const std::vector<double> ones(2 * 200, 1.0);
  feed(capped, ones, 2);
  CHECK(capped.curve(199).lag == std::vector<std::size_t>{0, 1, 2, 3, 4, 6, 8, 12});
  // Default levels cover lags of 2^20 frames; invalid parameters are refused.
  CHECK(MultiTauCorrelator(Kind::correlation, 1, 1).max_lag() >= (std::size_t{1} << 20));
  CHECK(MultiTauCorrelator(Kind::correlation, 1, 1).levels() == 18);
  CHECK_THROWS_AS(MultiTauCorrelator(Kind::correlation, 1, 1, 15, 2), InvalidInput);
  CHECK_THROWS_AS(MultiTauCorrelator(Kind::correlation, 1, 1, 16, 1), InvalidInput);
  CHECK_THROWS_AS(MultiTauCorrelator(Kind::correlation, 0, 1), InvalidInput);
  CHECK_THROWS_AS(MultiTauCorrelator(Kind::correlation, 1, 1, 16, 2, 100), InvalidInput);
  MultiTauCorrelator empty;
  CHECK_THROWS_AS(empty.add(ones.data(), 1), InvalidInput);
}

TEST_CASE("Multiple-tau VACF of AR(1) series matches the exact correlation", "[analysis]") {
  const std::size_t n = 400, frames = 4096, p = 16, m = 2;
  const int dim = 3;
  const std::size_t w = n * dim;
  const double rho = std::exp(-1.0 / 200.0);
  Rng rng(72);
  MultiTauCorrelator c(Kind::correlation, n, dim, p, m);
  std::vector<double> a(w);
  for (double& x : a) x = rng.normal();  // stationary start
  const double kick = std::sqrt(1.0 - rho * rho);
  for (std::size_t f = 0; f < frames; ++f) {
    c.add(a.data(), dim);
    for (double& x : a) x = rho * x + kick * rng.normal();
  }
  const MultiTauCurve r = c.curve(frames / 2);
  REQUIRE(r.lag.size() == 73);  // 16 + 7 * 8 + 1 (lag 2048 = 8 * 2^8)
  for (std::size_t i = 0; i < r.lag.size(); ++i) {
    // Level l and block lag j of this lag.
    std::size_t l = 0, B = 1;
    while (r.lag[i] / B >= p) ++l, B *= m;
    const std::size_t j = r.lag[i] / B, origins = r.origins[i];
    REQUIRE(origins == frames / B - j);
    // g(s): covariance of B-frame block means s blocks apart.
    const auto g = [&](long s) {
      const long bb = static_cast<long>(B);
      double sum = 0.0;
      for (long d = -(bb - 1); d <= bb - 1; ++d)
        sum += static_cast<double>(bb - std::abs(d)) *
               std::pow(rho, static_cast<double>(std::abs(s * bb + d)));
      return sum / static_cast<double>(bb * bb);
    };
    const auto jj = static_cast<long>(j), tt = static_cast<long>(origins);
    double var = 0.0;
    for (long s = -(tt - 1); s <= tt - 1; ++s)
      var += static_cast<double>(tt - std::abs(s)) * (g(s) * g(s) + g(s + jj) * g(s - jj));
    var /= static_cast<double>(tt) * static_cast<double>(tt);
    const double expect = dim * g(jj), sd = std::sqrt(dim * var / static_cast<double>(n));
    const double exact = dim * std::pow(rho, static_cast<double>(r.lag[i]));
    INFO("lag " << r.lag[i] << " value " << r.value[i] << " expected " << expect << " sd " << sd
                << " exact rho^lag " << exact);
    CHECK(std::abs(r.value[i] - expect) <= 5.5 * sd);
    // The block smoothing: a factor (sinh(B/400) / (B sinh(1/400)))^2 (the triangle sum in
    // closed form), 1 + (B^2 - 1) / (12 * 200^2) to leading order (multi_tau.hpp).
    const auto bd = static_cast<double>(B);
    const double factor = std::pow(std::sinh(bd / 400.0) / (bd * std::sinh(1.0 / 400.0)), 2);
    CHECK(expect / exact == Approx(factor).epsilon(1e-9));
    CHECK(factor - 1.0 >= (bd * bd - 1.0) / (12.0 * 200.0 * 200.0) - 1e-12);
  }
}

TEST_CASE("Multiple-tau MSD: exact for ballistic motion, linear for a random walk", "[analysis]") {
  const std::size_t n = 400, frames = 4096, p = 16, m = 2;
  const int dim = 3;
  const std::size_t w = n * dim;
  Rng rng(73);

  // Ballistic: integer positions, velocities and times.
  std::vector<double> x0(w), v(w), x(w);
  double v2 = 0.0;
  for (std::size_t k = 0; k < w; ++k) {
    x0[k] = std::floor(2000.0 * rng.uniform()) - 1000.0;
    v[k] = std::floor(11.0 * rng.uniform()) - 5.0;
    v2 += v[k] * v[k];
  }
  v2 /= static_cast<double>(n);  // <|v|^2> per particle
  MultiTauCorrelator ballistic(Kind::displacement, n, dim, p, m);
  for (std::size_t f = 0; f < frames; ++f) {
    for (std::size_t k = 0; k < w; ++k) x[k] = x0[k] + v[k] * static_cast<double>(f);
    ballistic.add(x.data(), dim);
  }
  const MultiTauCurve b = ballistic.curve(frames - 1);
  REQUIRE(b.lag.back() >= 2048);
  for (std::size_t i = 0; i < b.lag.size(); ++i) {
    const double lag = static_cast<double>(b.lag[i]);
    INFO("lag " << b.lag[i]);
    CHECK(b.value[i] == Approx(v2 * lag * lag).epsilon(1e-14).margin(0.0));
  }

  // Unit random walk: MSD = dim * lag.
  MultiTauCorrelator walk(Kind::displacement, n, dim, p, m);
  for (std::size_t k = 0; k < w; ++k) x[k] = 100.0 * rng.normal();
  for (std::size_t f = 0; f < frames; ++f) {
    walk.add(x.data(), dim);
    for (double& xk : x) xk += rng.normal();
  }
  const MultiTauCurve r = walk.curve(frames / 2);
  for (std::size_t i = 0; i < r.lag.size(); ++i) {
    std::size_t B = 1;
    while (r.lag[i] / B >= p) B *= m;
    const auto lag = static_cast<long>(r.lag[i]), bb = static_cast<long>(B),
               tt = static_cast<long>(r.origins[i]);
    double var = 0.0;  // per component, unit steps
    for (long s = -(tt - 1); s <= tt - 1; ++s) {
      const double overlap = static_cast<double>(std::max(0L, lag - bb * std::abs(s)));
      var += static_cast<double>(tt - std::abs(s)) * 2.0 * overlap * overlap;
    }
    var /= static_cast<double>(tt) * static_cast<double>(tt);
    const double sd = std::sqrt(dim * var / static_cast<double>(n));
    INFO("lag " << lag << " msd " << r.value[i] << " sd " << sd);
    CHECK(std::abs(r.value[i] - dim * static_cast<double>(lag)) <= 5.5 * sd);
  }
}

TEST_CASE("Multiple-tau memory does not grow with the number of frames", "[analysis]") {
  const std::size_t n = 50, p = 16, m = 2, levels = 8;
  const int dim = 3;
  MultiTauCorrelator c(Kind::correlation, n, dim, p, m, levels);
  const std::vector<double> frame(n * dim, 1.0);
  std::size_t at_1e3 = 0;
  for (std::size_t f = 1; f <= 100000; ++f) {
    c.add(frame.data(), dim);
    if (f == 1000) at_1e3 = c.bytes();  // all 8 levels in use after 2^7 frames
  }
  CHECK(at_1e3 == c.bytes());
  CHECK(c.bytes() == c.max_bytes());
  CHECK(c.max_bytes() == levels * (n * dim * (p + 1) + 2 * p + 3) * sizeof(double));

  // The recorder with default levels: within its bound after 1e5 frames, a bound that is
  // fixed by the first frame (18 levels here), far below storing the frames.
  VacfRecorder rec(10);
  Frame fr(3, 12);
  std::size_t bound = 0;
  for (std::size_t f = 0; f < 100000; ++f) {
    fr.v[0] = std::sin(0.01 * static_cast<double>(f));
    fr.x[0] = static_cast<double>(f);
    rec.observe(fr.snapshot(0.5 * static_cast<double>(f), true));
    if (f == 0) bound = rec.max_bytes();
  }
  CHECK(rec.max_bytes() == bound);
  // two correlators (velocity, position) of 8 error groups each (VacfRecorder::groups)
  CHECK(bound == 18 * (10 * 3 * (2 * 16 + 1) + 2 * ((8 + 1) * 16 + 3)) * sizeof(double));
  CHECK(rec.bytes() <= bound);
  CHECK(rec.bytes() * 10 < 100000 * 10 * 3 * 2 * sizeof(double));
}

TEST_CASE("VacfRecorder restored from a checkpoint continues bit for bit", "[analysis]") {
  const int dim = 2;
  const std::size_t n = 8;
  Rng rng(74);
  Frame fr(dim, n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < dim; ++k) fr.x[i * (dim + 1) + k] = rng.normal();
  const auto step = [&](VacfRecorder& a, VacfRecorder* b, std::size_t f) {
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < dim; ++k) {
        double& v = fr.v[i * (dim + 1) + k];
        v = 0.9 * v + rng.normal();
        fr.x[i * (dim + 1) + k] += 0.1 * v;
      }
    const Snapshot s = fr.snapshot(0.1 * static_cast<double>(f), true);
    a.observe(s);
    if (b) b->observe(s);
  };
  VacfRecorder orig(5, 8, 2);  // 5 of 8 particles, p = 8: several levels within 300 frames
  for (std::size_t f = 0; f < 300; ++f) step(orig, nullptr, f);
  test::TempDir dir;
  const std::string file = (dir.path / "state.hgck").string();
  {
    checkpoint::Writer out(file);
    orig.io(out);
    out.commit();
  }
  VacfRecorder back(1);  // other parameters: the checkpoint restores them
  {
    checkpoint::Reader in(file);
    back.io(in);
    in.finish();
  }
  CHECK(back.frames() == 300);
  CHECK(back.particles() == 5);
  CHECK(back.has_positions());
  CHECK(back.dt() == orig.dt());
  CHECK(back.bytes() == orig.bytes());
  for (std::size_t f = 300; f < 737; ++f) step(orig, &back, f);
  CHECK(back.lags() == orig.lags());
  CHECK(back.lags(736) == orig.lags(736));
  CHECK(back.origins(736) == orig.origins(736));
  CHECK(back.vacf(736) == orig.vacf(736));  // exact equality
  CHECK(back.msd(736) == orig.msd(736));
  CHECK(back.green_kubo() == orig.green_kubo());
  CHECK(orig.lags(736).back() == 512);  // 4 * 2^7: level 7 in use

  // A file of another layout is refused.
  {
    checkpoint::Writer out(file);
    MultiTauCorrelator c(Kind::correlation, 2, 2);
    c.io(out);
    out.commit();
  }
  checkpoint::Reader in(file);
  VacfRecorder other(3);
  CHECK_THROWS_AS(other.io(in), InvalidInput);
}

TEST_CASE("VacfRecorder: Green–Kubo on the multiple-tau grid and vacf.csv rows", "[analysis]") {
  // v(t) = cos(0.3 t + i) for particle i in every component; the trapezoid sum over the
  // grid of the recorder's own values must equal green_kubo().
  const int dim = 3;
  Frame fr(dim, 4);
  VacfRecorder rec(4);
  const double dt = 0.05;
  for (std::size_t f = 0; f < 200; ++f) {
    for (std::size_t i = 0; i < 4; ++i)
      for (int k = 0; k < dim; ++k)
        fr.v[i * (dim + 1) + k] = std::cos(0.3 * static_cast<double>(f) + static_cast<double>(i));
    rec.observe(fr.snapshot(dt * static_cast<double>(f), false));
  }
  const auto lags = rec.lags(), orig = rec.origins();
  const auto c = rec.vacf();
  REQUIRE(lags.size() == c.size());
  CHECK(lags.back() <= 100);
  CHECK(lags == std::vector<std::size_t>{0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12,
                                         13, 14, 15, 16, 18, 20, 22, 24, 26, 28, 30, 32, 36,
                                         40, 44, 48, 52, 56, 60, 64, 72, 80, 88, 96});
  CHECK(orig[0] == 200);
  CHECK(orig[17] == 100 - 9);  // lag 18 = 9 blocks of 2
  double s = 0.0;
  for (std::size_t i = 1; i < lags.size(); ++i)
    s += 0.5 * (c[i - 1] + c[i]) * static_cast<double>(lags[i] - lags[i - 1]);
  CHECK(rec.green_kubo() == Approx(s * dt / dim).epsilon(1e-14));
  // vacf.csv: a header and one row per lag, `lag,vacf,time` (no positions: no msd).
  test::TempDir dir;
  const std::string file = (dir.path / "state.hgck").string();
  rec.write_csv(file);
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  CHECK(line == "lag,vacf,time");
  std::size_t rows = 0;
  while (std::getline(in, line)) {
    REQUIRE(rows < lags.size());
    CHECK(std::stod(line.substr(0, line.find(','))) == static_cast<double>(lags[rows]));
    CHECK(std::stod(line.substr(line.rfind(',') + 1)) ==
          Approx(dt * static_cast<double>(lags[rows])).epsilon(1e-15));
    ++rows;
  }
  CHECK(rows == lags.size());
  CHECK_THROWS_AS(rec.msd(), InvalidInput);  // no positions
  CHECK_THROWS_AS(rec.vacf(200), InvalidInput);
  VacfRecorder one(4);
  one.observe(fr.snapshot(0.0, false));
  CHECK_THROWS_AS(one.vacf(), InvalidInput);
  CHECK_THROWS_AS(VacfRecorder(0), InvalidInput);
  CHECK_THROWS_AS(VacfRecorder(10, 16, 3), InvalidInput);
}

TEST_CASE("Multiple-tau groups: each group's curve is its channels' curve, one group the "
          "plain sums", "[analysis]") {
  // 10 channels in 3 groups (4, 3, 3 channels: floor(c G / 10)). Group g's curve must be
  // that of a correlator fed only its channels (to round-off: the same pairs, summed in
  // the same order), the channel-weighted mean of the groups the whole curve, and one group
  // the correlator without groups bit for bit.
  Rng rng(5);
  const std::size_t n = 10, frames = 300;
  const int dim = 2;
  std::vector<double> v(frames * n * dim);
  for (double& x : v) x = rng.normal();
  for (const auto kind : {Kind::correlation, Kind::displacement}) {
    MultiTauCorrelator all(kind, n, dim, 16, 2, 0, 3), one(kind, n, dim, 16, 2, 0, 1),
        plain(kind, n, dim);
    std::vector<MultiTauCorrelator> parts;
    for (std::size_t g = 0; g < 3; ++g)
      parts.emplace_back(kind, all.group_begin(g + 1) - all.group_begin(g), dim);
    REQUIRE(all.group_begin(1) == 4);
    REQUIRE(all.group_begin(2) == 7);
    for (std::size_t f = 0; f < frames; ++f) {
      const double* x = v.data() + f * n * dim;
      all.add(x, dim), one.add(x, dim), plain.add(x, dim);
      for (std::size_t g = 0; g < 3; ++g) parts[g].add(x + all.group_begin(g) * dim, dim);
    }
    const MultiTauCurve c = all.curve(150);
    CHECK(one.curve(150).value == plain.curve(150).value);  // bit for bit
    std::vector<double> weighted(c.value.size(), 0.0);
    for (std::size_t g = 0; g < 3; ++g) {
      const MultiTauCurve cg = all.group_curve(g, 150), ref = parts[g].curve(150);
      REQUIRE(cg.lag == c.lag);
      REQUIRE(ref.lag == c.lag);
      const double share =
          static_cast<double>(all.group_begin(g + 1) - all.group_begin(g)) / n;
      for (std::size_t i = 0; i < c.lag.size(); ++i) {
        CHECK(cg.value[i] == Approx(ref.value[i]).epsilon(1e-12).margin(1e-14));
        weighted[i] += share * cg.value[i];
      }
    }
    for (std::size_t i = 0; i < c.lag.size(); ++i)
      CHECK(weighted[i] == Approx(c.value[i]).epsilon(1e-12).margin(1e-14));
  }
  CHECK_THROWS_AS(MultiTauCorrelator(Kind::correlation, 3, 1, 16, 2, 0, 4), InvalidInput);
  CHECK_THROWS_AS(MultiTauCorrelator(Kind::correlation, 3, 1, 16, 2, 0, 0), InvalidInput);
}
