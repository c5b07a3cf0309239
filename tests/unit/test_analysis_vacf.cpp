// VACF and MSD (analysis/vacf.hpp, vacf_recorder.hpp).
//
// 1. FFT (Wiener–Khinchin, zero-padded) against the direct double sum: equal to 1e-12 of
//    vacf(0) (and of max msd) at every lag: pure round-off, deterministic.
// 2. Ornstein–Uhlenbeck velocities, dv = -v/tau dt + sqrt(2 kT/(m tau)) dW, sampled exactly
//    (Gillespie 1996, Phys. Rev. E 54:2084, exact joint update of v and x = integral v dt):
//    exact VACF D (kT/m) exp(-t/tau), self-diffusion D_s = (kT/m) tau. Green–Kubo and the
//    MSD slope must agree with D_s and with each other. Tolerances: over 40 other seeds
//    (n = 1000, D = 3, 2000 frames, h = 0.1 tau) the sample sd of (D_GK - D_s)/D_s was
//    0.0081, of (D_MSD - D_s)/D_s 0.0099 and of (D_GK - D_MSD)/D_s 0.0045 (the two share
//    noise), means consistent with 0. The test allows 6 sd (0.049, 0.060, 0.027); allowing
//    for the 11% uncertainty of a 40-sample sd that is > 5.3 true sd, false-failure
//    probability < 1e-7 each if the errors are normal.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hypergas/analysis/vacf.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "hypergas/error.hpp"
#include "hypergas/rng.hpp"
#include "support/correlation.hpp"

using namespace hypergas;
using namespace hypergas::analysis;
using test_support::msd_direct;
using test_support::vacf_direct;

namespace {
struct Series {
  std::vector<double> v, x;
};

// n * dim independent OU channels, frames spaced h, relaxation time tau, kT/m = a.
Series ornstein_uhlenbeck(Rng& rng, std::size_t n, int dim, std::size_t frames, double h,
                          double tau, double a) {
  const std::size_t c = n * static_cast<std::size_t>(dim);
  const double e = std::exp(-h / tau);
  // Covariance of the noise (eta_v, eta_x) of one step (Gillespie 1996, eqs. 2.24-2.26).
  const double svv = a * (1 - e * e);
  const double sxx = a * tau * tau * (2 * h / tau - 3 + 4 * e - e * e);
  const double svx = a * tau * (1 - e) * (1 - e);
  const double l11 = std::sqrt(svv), l21 = svx / l11, l22 = std::sqrt(sxx - l21 * l21);
  Series s;
  s.v.resize(frames * c);
  s.x.resize(frames * c);
  for (std::size_t k = 0; k < c; ++k) {
    s.v[k] = std::sqrt(a) * rng.normal();  // stationary start
    s.x[k] = 10.0 * rng.normal();          // arbitrary offsets: the MSD must not care
  }
  for (std::size_t f = 1; f < frames; ++f)
    for (std::size_t k = 0; k < c; ++k) {
      const double v0 = s.v[(f - 1) * c + k], z1 = rng.normal(), z2 = rng.normal();
      s.v[f * c + k] = e * v0 + l11 * z1;
      s.x[f * c + k] = s.x[(f - 1) * c + k] + tau * (1 - e) * v0 + l21 * z1 + l22 * z2;
    }
  return s;
}
}  // namespace

TEST_CASE("VACF and MSD by FFT equal the direct sums to 1e-12", "[analysis]") {
  Rng rng(41);
  for (std::size_t frames : {1u, 2u, 17u, 64u, 301u}) {
    for (int dim : {1, 3, 6}) {
      INFO("frames " << frames << " dim " << dim);
      const std::size_t n = 7;
      // Correlated series with a non-zero mean (the hard case for round-off).
      Series s = ornstein_uhlenbeck(rng, n, dim, frames, 0.3, 1.0, 2.0);
      for (double& v : s.v) v += 0.5;
      const std::size_t lag = frames - 1;
      const auto fast = vacf(s.v, frames, n, dim, lag);
      const auto slow = vacf_direct(s.v, frames, n, dim, lag);
      const auto mf = msd(s.x, frames, n, dim, lag);
      const auto ms = msd_direct(s.x, frames, n, dim, lag);
      double mmax = 0;
      for (double m : ms) mmax = std::max(mmax, m);
      for (std::size_t l = 0; l <= lag; ++l) {
        CHECK(std::abs(fast[l] - slow[l]) <= 1e-12 * slow[0]);
        CHECK(std::abs(mf[l] - ms[l]) <= 1e-12 * std::max(mmax, 1e-300));
      }
    }
  }
  const std::vector<double> v(12, 1.0);
  CHECK_THROWS_AS(vacf(v, 4, 1, 3, 4), InvalidInput);  // lag >= frames
  CHECK_THROWS_AS(vacf(v, 4, 2, 3, 1), InvalidInput);  // wrong size
}

TEST_CASE("Ornstein–Uhlenbeck: Green–Kubo and MSD slope give D_s = (kT/m) tau", "[analysis]") {
  const double tau = 1.0, a = 1.0, h = 0.1;
  const std::size_t n = 1000, frames = 2000;
  const int dim = 3;
  Rng rng(42);
  const Series s = ornstein_uhlenbeck(rng, n, dim, frames, h, tau, a);
  const auto c = vacf(s.v, frames, n, dim, 400);
  // The VACF itself, 3 exp(-t): at lag 0 its relative sd is ~ sqrt(2 tau / (n D frames h))
  // = 0.0026 (correlated frames), at lag 10 about sqrt(2) times more; 5 sd allowed.
  CHECK(c[0] == Approx(dim * a).epsilon(0.013));
  CHECK(c[10] == Approx(dim * a * std::exp(-1.0)).epsilon(0.02));
  // Green–Kubo to 10 tau: truncation e^-10 and trapezoid (h/2) coth(h/2) - 1 = h^2/12 = 8e-4.
  const double gk = green_kubo_diffusion(c, h, dim, 100);
  // MSD slope on t in [10, 20] tau, where MSD = 2 D D_s (t - tau (1 - e^-t/tau)).
  const auto m = msd(s.x, frames, n, dim, 200);
  const Estimate em = msd_diffusion(m, h, dim, 100, 200);
  INFO("D_GK " << gk << " D_MSD " << em.value << " +- " << em.error);
  CHECK(gk == Approx(a * tau).epsilon(0.049));
  CHECK(em.value == Approx(a * tau).epsilon(0.060));
  CHECK(std::abs(gk - em.value) < 0.027 * a * tau);
}

TEST_CASE("VacfRecorder follows the first particles and checks the spacing", "[analysis]") {
  const std::size_t n = 5;
  const int dim = 2;
  Rng rng(43);
  const Series s = ornstein_uhlenbeck(rng, n, dim, 50, 0.2, 1.0, 1.0);
  VacfRecorder rec(3);  // keeps the first 3 of 5 particles
  std::vector<double> vbuf(n * 2), xbuf(n * 2);
  for (std::size_t f = 0; f < 50; ++f) {
    for (std::size_t i = 0; i < n * 2; ++i) {
      vbuf[i] = s.v[f * n * dim + i];
      xbuf[i] = s.x[f * n * dim + i];
    }
    Snapshot snap;
    snap.dim = dim;
    snap.n = n;
    snap.stride = 2;
    snap.time = 0.2 * static_cast<double>(f) + 5.0;
    snap.velocities = vbuf.data();
    snap.positions = xbuf.data();
    rec.observe(snap);
  }
  CHECK(rec.frames() == 50);
  CHECK(rec.particles() == 3);
  CHECK(rec.dt() == Approx(0.2));
  // The recorder's VACF is the VACF of the first 3 particles, at the multiple-tau lags up
  // to 25 = frames / 2: every lag below p = 16 (exact), then every second lag (level 1,
  // the VACF of the means of frame pairs; multi_tau.hpp).
  std::vector<double> first3, x3, pairs;
  for (std::size_t f = 0; f < 50; ++f)
    for (std::size_t i = 0; i < 3 * dim; ++i) {
      first3.push_back(s.v[f * n * dim + i]);
      x3.push_back(s.x[f * n * dim + i]);
    }
  for (std::size_t b = 0; b < 25; ++b)
    for (std::size_t i = 0; i < 3 * dim; ++i)
      pairs.push_back(0.5 * (first3[2 * b * 3 * dim + i] + first3[(2 * b + 1) * 3 * dim + i]));
  const auto ref = vacf_direct(first3, 50, 3, dim, 15);
  const auto ref_pairs = vacf_direct(pairs, 25, 3, dim, 12);
  const auto ref_msd = msd_direct(x3, 50, 3, dim, 15);
  const auto lags = rec.lags();
  const auto got = rec.vacf();
  const auto got_msd = rec.msd();
  REQUIRE(lags == std::vector<std::size_t>{0,  1,  2,  3,  4,  5,  6,  7,  8,  9, 10,
                                           11, 12, 13, 14, 15, 16, 18, 20, 22, 24});
  REQUIRE(got.size() == lags.size());
  REQUIRE(got_msd.size() == lags.size());
  for (std::size_t l = 0; l < 16; ++l) {
    CHECK(got[l] == Approx(ref[l]).margin(1e-12 * ref[0]));
    CHECK(got_msd[l] == Approx(ref_msd[l]).margin(1e-12 * ref_msd[15]));
  }
  for (std::size_t i = 16; i < lags.size(); ++i)
    CHECK(got[i] == Approx(ref_pairs[lags[i] / 2]).margin(1e-12 * ref[0]));
  // A snapshot off the time grid is refused.
  Snapshot late;
  late.dim = dim;
  late.n = n;
  late.stride = 2;
  late.time = 5.0 + 0.2 * 50 + 0.05;
  late.velocities = vbuf.data();
  late.positions = xbuf.data();
  CHECK_THROWS_AS(rec.observe(late), InvalidInput);
}

namespace {
// A VacfRecorder of all n particles fed the frames of s (spacing h, positions included).
VacfRecorder recorded(const Series& s, std::size_t n, int dim, std::size_t frames, double h) {
  VacfRecorder rec(n);
  for (std::size_t f = 0; f < frames; ++f) {
    Snapshot snap;
    snap.dim = dim;
    snap.n = n;
    snap.stride = dim;
    snap.time = h * static_cast<double>(f);
    snap.velocities = s.v.data() + f * n * static_cast<std::size_t>(dim);
    snap.positions = s.x.data() + f * n * static_cast<std::size_t>(dim);
    rec.observe(snap);
  }
  return rec;
}
}  // namespace

TEST_CASE("VacfRecorder::diffusion: the plateau rule on Ornstein-Uhlenbeck velocities",
          "[analysis]") {
  // Exact D_s = a tau = 1 (a = kT/m = 1, tau = 1), sampled at h = 0.1 tau: the trapezoid
  // rule is high by h^2/12 = 8e-4 (relative), below the statistical error. The recorder's
  // groups of particles (8) give the statistical error; an exponential VACF has no tail, so
  // the remainder and the truncation error are near 0. Green-Kubo and Einstein (the MSD
  // slope around the same cut) must each be within 5 of their stated errors of D_s: the
  // errors come from 8 groups, so for a new seed a false failure has probability
  // P(|t_7| > 5) = 0.16 %; with this fixed seed the test is deterministic. The errors must
  // also be honest in size: between 0.2 % and 3 % of D_s (n = 1000 particles, 2000 frames
  // of 0.1 tau: about 200 / 5 independent stretches per particle give 1 / sqrt(1000 * 40)
  // = 0.5 % for the whole set).
  const std::size_t n = 1000, frames = 2000;
  const int dim = 3;
  const double h = 0.1;
  Rng rng(2027);
  const Series s = ornstein_uhlenbeck(rng, n, dim, frames, h, 1.0, 1.0);
  const VacfRecorder::Diffusion d = recorded(s, n, dim, frames, h).diffusion(0.2);
  INFO("GK " << d.green_kubo << " +- " << d.statistical_error << " (stat) +- "
             << d.truncation_error << " (cut at " << d.cut_time << "), Einstein " << d.einstein
             << " +- " << d.einstein_error);
  CHECK(std::abs(d.green_kubo - 1.0) <= 5.0 * d.error);
  CHECK(std::abs(d.einstein - 1.0) <= 5.0 * d.einstein_error);
  CHECK(d.statistical_error > 0.002);
  CHECK(d.error < 0.03);
  CHECK(d.einstein_error < 0.03);
  // the cut: at least 5 "mean free times" (1.0) and 3 integral times (3 tau)
  CHECK(d.cut_time >= 3.0 - 1e-12);
  CHECK(d.cut_time <= 2.0 / 3.0 * h * static_cast<double>(frames / 2));
}

TEST_CASE("VacfRecorder::diffusion: the stated errors match the spread over seeds",
          "[analysis]") {
  // Eight independent Ornstein-Uhlenbeck runs (seeds 101..108, n = 1000, D = 3, 2000
  // frames of 0.1 tau, exact D_s = 1): the sample sd of their Green-Kubo values, and of
  // their Einstein values, must be within a factor 2 of the root mean square of the errors
  // each run states. The sd of 8 samples has 7 degrees of freedom and each stated error 7
  // (8 groups), the mean square of eight of them 56: the ratio falls outside [1/2, 2] with
  // probability about 3 % for a new set of seeds (mostly from the low side of the 8-sample
  // sd); with these fixed seeds the test is deterministic (ratios 1.46 and 1.42). Over 32
  // seeds (101..132) the ratios are 1.19 and 1.26: the stated errors run about 20 % low,
  // likely because the cut is the candidate where the noisy stated error is smallest.
  const std::size_t n = 1000, frames = 2000, runs = 8;
  const int dim = 3;
  const double h = 0.1;
  std::vector<double> gk, ein;
  double gk_ms = 0.0, ein_ms = 0.0;
  for (std::size_t r = 0; r < runs; ++r) {
    Rng rng(101 + r);
    const Series s = ornstein_uhlenbeck(rng, n, dim, frames, h, 1.0, 1.0);
    const VacfRecorder::Diffusion d = recorded(s, n, dim, frames, h).diffusion(0.2);
    REQUIRE(std::isfinite(d.error));
    REQUIRE(std::isfinite(d.einstein_error));
    gk.push_back(d.green_kubo);
    ein.push_back(d.einstein);
    gk_ms += d.error * d.error / static_cast<double>(runs);
    ein_ms += d.einstein_error * d.einstein_error / static_cast<double>(runs);
  }
  const auto sd = [](const std::vector<double>& x) {
    double m = 0.0, ss = 0.0;
    for (double v : x) m += v / static_cast<double>(x.size());
    for (double v : x) ss += (v - m) * (v - m);
    return std::sqrt(ss / static_cast<double>(x.size() - 1));
  };
  const double gk_ratio = sd(gk) / std::sqrt(gk_ms), ein_ratio = sd(ein) / std::sqrt(ein_ms);
  INFO("Green-Kubo: sd " << sd(gk) << ", stated " << std::sqrt(gk_ms) << "; Einstein: sd "
                         << sd(ein) << ", stated " << std::sqrt(ein_ms));
  CHECK(gk_ratio > 0.5);
  CHECK(gk_ratio < 2.0);
  CHECK(ein_ratio > 0.5);
  CHECK(ein_ratio < 2.0);
}
