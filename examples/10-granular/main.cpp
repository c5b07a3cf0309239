// Example 10 -- granular gases: the homogeneous cooling state in 2D, 3D and 6D, Haff's law
// from both engines, and the clustering instability of a 2D gas of inelastic disks.
//
// The story. A granular gas is a gas of grains: every collision removes a fraction
// 1 - alpha^2 of the normal relative kinetic energy (alpha the coefficient of normal
// restitution). Left alone it cools without bound. Kinetic theory predicts that it cools
// through a homogeneous cooling state (HCS): a velocity distribution that keeps its shape
// in the scaled velocity c = v / v_T(t) while the temperature falls, and that shape is not
// a Maxwellian. Its first measure is the fourth cumulant a2 = D/(D+2) <v^4>/<v^2>^2 - 1
// (0 for a Maxwellian); van Noije & Ernst's first Sonine approximation (a2_hcs) gives it in
// closed form. a2 changes sign at alpha = 1/sqrt(2): weakly inelastic gases have fewer fast
// particles than a Maxwellian, strongly inelastic ones more. With the shape constant, the
// temperature follows Haff's law T(t) = T0 / (1 + t/t0)^2, t0 = 2 / zeta* (zeta* the cooling
// rate per mean collision time at T0, granular/theory.hpp).
//
// Part 1 measures a2 of the HCS by DSMC (the spatially homogeneous Boltzmann equation, kept
// in scaled velocities: dsmc/granular.hpp) for alpha = 0.1 .. 0.95 in 2D, 3D and 6D, beside
// the first and second Sonine approximations.
//
// Part 2 follows Haff's law in 3D at alpha = 0.8 with both engines: DSMC's real_time is
// already in mean collision times at T0; EDMD (a dilute gas, packing 0.02) is equilibrated
// elastically, its collision frequency nu measured, then quenched (set_restitution), and
// its time multiplied by nu. Both are set beside 1/(1 + t/t0)^2 with the Sonine t0, and
// their cooling per collision, -d ln T / d(collisions per particle), is compared: a number
// that does not depend on the density (Enskog's factor g(sigma+) speeds up the collisions
// and the cooling alike).
//
// Part 3 shows what DSMC cannot: the HCS is unstable in space. In a large enough box of
// inelastic disks (2D EDMD, packing 0.25, alpha = 0.8) the denser regions collide more
// often, cool faster, lose pressure and draw in more grains: first vortices (the shear mode),
// then clusters and voids (Goldhirsch & Zanetti, Phys. Rev. Lett. 70, 1619 (1993)). The
// program writes the positions with their local density at four instants, the density
// contrast and correlation length of the coarse-grained density, and the temperature
// against Haff's law, which the clustered gas leaves.
//
// Usage: example_10 [--short]  (writes a2_vs_alpha.csv, haff.csv, clustering.csv and
// snapshot_1.csv .. snapshot_4.csv in the current folder; exits 1 when a check fails)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "hypergas/analysis/estimates.hpp"
#include "hypergas/analysis/fit.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/granular/theory.hpp"
#include "hypergas/observer.hpp"

using namespace hypergas;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

using analysis::MeanSe;
using analysis::mean_se;

/// The blocks of the errors: 8 consecutive stretches of the second half of a run.
constexpr int blocks = 8;

/// Rows of x (increasing) in [lo, hi) split into `blocks` stretches of equal length in x:
/// the row ranges [b_k, e_k).
std::vector<std::array<std::size_t, 2>> stretches(const std::vector<double>& x, double lo,
                                                  double hi) {
  std::vector<std::array<std::size_t, 2>> r;
  for (int k = 0; k < blocks; ++k) {
    const double a = lo + (hi - lo) * k / blocks, b = lo + (hi - lo) * (k + 1) / blocks;
    const auto first = std::lower_bound(x.begin(), x.end(), a) - x.begin();
    const auto last = std::lower_bound(x.begin(), x.end(), k + 1 == blocks ? hi * 1.0000001 : b) -
                      x.begin();
    r.push_back({static_cast<std::size_t>(first), static_cast<std::size_t>(last)});
  }
  return r;
}

/// A cooling run as rows: time in mean collision times at T0, T/T0, collisions per particle
/// since the start of the cooling, a2.
struct Cooling {
  std::vector<double> t, T, cpp, a2;

  /// -d ln T / d(collisions per particle) over the second half of the collisions, mean and
  /// standard error of the 8 stretches' slopes.
  MeanSe cooling_per_collision() const {
    std::vector<double> lnT, v;
    for (const double x : T) lnT.push_back(std::log(x));
    for (const auto& [b, e] : stretches(cpp, 0.5 * cpp.back(), cpp.back()))
      v.push_back(-analysis::line_slope(cpp, lnT, b, e));
    return mean_se(v);
  }
  /// Haff's t0 from the slope of (T/T0)^(-1/2) against t over the second half of the
  /// collisions (where the shape has relaxed): T^(-1/2) = 1 + t/t0.
  MeanSe haff_t0() const {
    std::vector<double> inv, v;
    for (const double x : T) inv.push_back(1.0 / std::sqrt(x));
    for (const auto& [b, e] : stretches(cpp, 0.5 * cpp.back(), cpp.back()))
      v.push_back(1.0 / analysis::line_slope(t, inv, b, e));
    return mean_se(v);
  }
};

// ---- Part 1 ---------------------------------------------------------------------------

/// a2 of the HCS by DSMC: hard spheres from a Maxwellian at restitution alpha, run to
/// `until` mean collision times of the scaled clock with a row every 0.5, in `replicas`
/// independent copies; the mean of a2 over the second half of each, and its error from
/// the 8 consecutive blocks of every copy (8 x replicas block means).
template <int D>
MeanSe hcs_a2(double alpha, std::size_t n, double until, int replicas, std::uint64_t seed) {
  std::vector<double> v;
  for (int r = 0; r < replicas; ++r) {
    dsmc::Config cfg;
    cfg.n = n;
    cfg.init = InitialState::maxwell;
    cfg.restitution = alpha;
    cfg.seed = seed + 1000 * r;
    dsmc::Engine<D, dsmc::HardSpheres> e(cfg);
    analysis::MomentsRecorder rec;
    e.run_until(until, &rec, 0.5);
    const std::vector<double> a2 = rec.column("a2"), t = rec.column("time");
    for (const auto& [b, e2] : stretches(t, 0.5 * until, until))
      v.push_back(analysis::range_mean(a2, b, e2));
  }
  return mean_se(v);
}

// ---- Part 2 ---------------------------------------------------------------------------

/// DSMC cooling from a Maxwellian (D = 3) to `until` of the scaled clock, a row every 0.25.
Cooling dsmc_cooling(double alpha, std::size_t n, double until) {
  dsmc::Config cfg;
  cfg.n = n;
  cfg.init = InitialState::maxwell;
  cfg.restitution = alpha;
  cfg.seed = 11;
  dsmc::Engine<3, dsmc::HardSpheres> e(cfg);
  analysis::MomentsRecorder rec;
  e.run_until(until, &rec, 0.25);
  Cooling c;
  c.t = rec.column("real_time");
  c.T = rec.column("T");
  c.cpp = rec.column("collisions_per_particle");
  c.a2 = rec.column("a2");
  for (double& x : c.T) x /= e.initial_temperature();
  return c;
}

/// EDMD at packing eta (D = 3): elastic equilibration to `t_eq`, the collision frequency
/// nu (collisions per particle per unit time) measured over its second half, then the
/// quench to alpha and rows at the times t_k / nu after it (t_k in mean collision times at
/// T0, `per_decade` per decade from 0.05 to t_max).
Cooling edmd_cooling(double alpha, std::size_t n, double eta, double t_eq, double t_max,
                     int per_decade, double& nu) {
  edmd::Config cfg;
  cfg.n = n;
  cfg.packing = eta;
  cfg.seed = 13;
  edmd::Engine<3> e(cfg);
  e.run_until(0.5 * t_eq);
  e.reset_observables();
  e.run_until(t_eq);
  nu = e.collision_rate();
  const double T0 = e.temperature();
  const std::uint64_t c0 = e.collisions();
  e.set_restitution(alpha);
  analysis::MomentsRecorder rec;
  Cooling c;
  const auto row = [&] {
    e.observe(rec);
    c.t.push_back((e.time() - t_eq) * nu);
    c.T.push_back(e.temperature() / T0);
    c.cpp.push_back(2.0 * static_cast<double>(e.collisions() - c0) / static_cast<double>(n));
    c.a2.push_back(rec.rows().back()[std::find(rec.columns().begin(), rec.columns().end(), "a2") -
                                     rec.columns().begin()]);
  };
  row();
  const int k_max = static_cast<int>(std::lround(per_decade * std::log10(t_max / 0.05)));
  for (int k = 0; k <= k_max; ++k) {
    e.run_until(t_eq + 0.05 * std::pow(10.0, static_cast<double>(k) / per_decade) / nu);
    row();
  }
  return c;
}

// ---- Part 3 ---------------------------------------------------------------------------

/// Keeps the positions of an EDMD snapshot, wrapped into the box.
struct Positions final : Observer {
  std::vector<double> xy;  // x0, y0, x1, y1, ...
  double box = 0.0;
  void observe(const Snapshot& s) override {
    box = s.box;
    xy.resize(2 * s.n);
    for (std::size_t i = 0; i < s.n; ++i)
      for (int k = 0; k < 2; ++k) {
        double x = std::fmod(s.positions[i * s.stride + k], box);
        if (x < 0.0) x += box;
        if (x >= box) x -= box;
        xy[2 * i + k] = x;
      }
  }
};

/// Counts per cell of an m x m grid over the box.
std::vector<double> cell_counts(const Positions& p, int m) {
  std::vector<double> c(static_cast<std::size_t>(m) * m, 0.0);
  const double w = m / p.box;
  for (std::size_t i = 0; i < p.xy.size() / 2; ++i) {
    const int a = std::min(m - 1, static_cast<int>(p.xy[2 * i] * w));
    const int b = std::min(m - 1, static_cast<int>(p.xy[2 * i + 1] * w));
    c[static_cast<std::size_t>(a) * m + b] += 1.0;
  }
  return c;
}

/// Local packing fraction at each disk: the disks whose centres lie within R = 3 sigma
/// (itself included) times the area of a disk, over pi R^2.
std::vector<double> local_packing(const Positions& p) {
  constexpr double R = 3.0;
  const int m = std::max(3, static_cast<int>(p.box / R));
  const double w = m / p.box;
  const std::size_t n = p.xy.size() / 2;
  std::vector<std::vector<std::uint32_t>> cells(static_cast<std::size_t>(m) * m);
  const auto cell = [&](std::size_t i, int k) {
    return std::min(m - 1, static_cast<int>(p.xy[2 * i + k] * w));
  };
  for (std::size_t i = 0; i < n; ++i)
    cells[static_cast<std::size_t>(cell(i, 0)) * m + cell(i, 1)].push_back(
        static_cast<std::uint32_t>(i));
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int a = cell(i, 0), b = cell(i, 1);
    int count = 0;
    for (int da = -1; da <= 1; ++da)
      for (int db = -1; db <= 1; ++db) {
        const auto& c = cells[static_cast<std::size_t>((a + da + m) % m) * m + (b + db + m) % m];
        for (const std::uint32_t j : c) {
          double dx = p.xy[2 * j] - p.xy[2 * i], dy = p.xy[2 * j + 1] - p.xy[2 * i + 1];
          dx -= p.box * std::round(dx / p.box);
          dy -= p.box * std::round(dy / p.box);
          if (dx * dx + dy * dy <= R * R) ++count;
        }
      }
    out[i] = count * (0.25 * std::numbers::pi) / (std::numbers::pi * R * R);
  }
  return out;
}

/// The coarse-grained density of a snapshot: packing fraction of ~10 sigma cells (largest,
/// smallest, their ratio, relative standard deviation) and the correlation length of the
/// density on ~5 sigma cells: the first zero of the radially averaged correlation C(r).
struct Coarse {
  double cell = 0, max = 0, min = 0, rel_sd = 0, zero = 0;
};

Coarse coarse_grain(const Positions& p) {
  Coarse r;
  const int m10 = std::max(2, static_cast<int>(std::lround(p.box / 10.0)));
  r.cell = p.box / m10;
  const double disk = 0.25 * std::numbers::pi / (r.cell * r.cell);
  const std::vector<double> c10 = cell_counts(p, m10);
  r.max = *std::max_element(c10.begin(), c10.end()) * disk;
  r.min = *std::min_element(c10.begin(), c10.end()) * disk;
  const MeanSe ms = mean_se(c10);
  r.rel_sd = ms.se * std::sqrt(static_cast<double>(c10.size())) / ms.mean;
  // correlation of the density on the 5-sigma grid, radially averaged in bins of one cell
  const int m = std::max(4, static_cast<int>(std::lround(p.box / 5.0)));
  std::vector<double> c = cell_counts(p, m);
  const double mean = static_cast<double>(p.xy.size() / 2) / (static_cast<double>(m) * m);
  for (double& x : c) x -= mean;
  const int h = m / 2;
  std::vector<double> sum(h + 1, 0.0), cnt(h + 1, 0.0);
  for (int dx = -h; dx < h; ++dx)
    for (int dy = -h; dy < h; ++dy) {
      const int bin = static_cast<int>(std::lround(std::sqrt(double(dx * dx + dy * dy))));
      if (bin > h) continue;
      double s = 0.0;
      for (int a = 0; a < m; ++a)
        for (int b = 0; b < m; ++b)
          s += c[static_cast<std::size_t>(a) * m + b] *
               c[static_cast<std::size_t>((a + dx + m) % m) * m + (b + dy + m) % m];
      sum[bin] += s;
      cnt[bin] += 1.0;
    }
  const double w = p.box / m;
  r.zero = nan;
  for (int k = 1; k <= h; ++k) {
    const double y0 = sum[k - 1] / cnt[k - 1], y1 = sum[k] / cnt[k];
    if (y1 <= 0.0) {
      r.zero = w * (k - 1 + y0 / (y0 - y1));
      break;
    }
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const bool short_run = argc > 1 && std::strcmp(argv[1], "--short") == 0;
  const auto t_start = std::chrono::steady_clock::now();
  const auto wall = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  };
  bool ok = true;

  // ---- Part 1: a2 of the HCS against alpha ---------------------------------------------
  const std::vector<double> alphas =
      short_run ? std::vector<double>{0.3, 0.5, 0.9}
                : std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95};
  const std::size_t n1 = short_run ? 20000 : 50000;
  const double until1 = 40.0;
  const int replicas = short_run ? 2 : 4;
  fmt::print("Part 1: a2 of the homogeneous cooling state (DSMC, N = {}, {} mean collision "
             "times, mean of the second half, {} copies)\n",
             n1, until1, replicas);
  fmt::print("  D  alpha   a2 measured          first Sonine  second Sonine (a3)    band\n");
  std::vector<std::vector<double>> rows1;
  MeanSe a2_3d_05;
  for (const int d : {2, 3, 6})
    for (std::size_t k = 0; k < alphas.size(); ++k) {
      const double alpha = alphas[k];
      const std::uint64_t seed = 100 + 10 * d + k;
      const MeanSe a2 = d == 2   ? hcs_a2<2>(alpha, n1, until1, replicas, seed)
                        : d == 3 ? hcs_a2<3>(alpha, n1, until1, replicas, seed)
                                 : hcs_a2<6>(alpha, n1, until1, replicas, seed);
      const double s1 = granular::a2_hcs(alpha, d);
      const auto s2 = granular::hcs_second_sonine(alpha, d);
      fmt::print("  {}  {:.2f}   {:8.5f} +- {:.5f}   {:8.5f}      {:8.5f} ({:8.5f})   {:.4f}\n", d,
                 alpha, a2.mean, a2.se, s1, s2.a2, s2.a3, granular::hcs_band(alpha, d));
      rows1.push_back({double(d), alpha, a2.mean, a2.se, s1, s2.a2});
      if (d == 3 && alpha == 0.5) a2_3d_05 = a2;
    }
  analysis::write_csv("a2_vs_alpha.csv",
                      {"dim", "alpha", "a2", "a2_error", "a2_sonine", "a2_second_sonine"}, rows1);
  fmt::print("  a2 changes sign at alpha = 1/sqrt(2) = {:.4f} in every D (first Sonine)\n",
             1.0 / std::sqrt(2.0));
  // Check 1: 3D, alpha = 0.5 within the Sonine band (twice the first-to-second Sonine
  // change) plus 4 standard errors. The error comes from 8 blocks of each copy (16 in the
  // short run: Student t with 15 degrees of freedom): a gas whose a2 lies inside the band
  // fails with probability below P(|t_15| > 4) = 0.12 %; the seeds are fixed, so a given
  // build passes or fails every time.
  {
    const double band = granular::hcs_band(0.5, 3), ref = granular::a2_hcs(0.5, 3);
    const bool pass = std::abs(a2_3d_05.mean - ref) < band + 4.0 * a2_3d_05.se;
    fmt::print("  check: 3D alpha = 0.5: |{:.5f} - {:.5f}| < {:.4f} + 4 x {:.5f}: {}\n",
               a2_3d_05.mean, ref, band, a2_3d_05.se, pass ? "yes" : "NO");
    ok = ok && pass;
  }
  fmt::print("  ({:.1f} s)\n\n", wall());

  // ---- Part 2: Haff's law from both engines (3D, alpha = 0.8) ---------------------------
  const double alpha2 = 0.8;
  const double a2s = granular::a2_hcs(alpha2, 3);
  const double t0_sonine = granular::haff_t0(alpha2, 3, a2s);
  const double eta2 = 0.02;
  const std::size_t n_dsmc = short_run ? 20000 : 50000, n_edmd = short_run ? 1000 : 8000;
  const Cooling ds = dsmc_cooling(alpha2, n_dsmc, short_run ? 50.0 : 70.0);
  double nu = 0.0;
  const Cooling md = edmd_cooling(alpha2, n_edmd, eta2, short_run ? 40.0 : 80.0,
                                  short_run ? 200.0 : 1000.0, short_run ? 25 : 50, nu);
  const double chi = granular::chi_carnahan_starling(eta2);
  fmt::print("Part 2: Haff's law, 3D, alpha = {} (DSMC N = {}; EDMD N = {}, packing {})\n",
             alpha2, n_dsmc, n_edmd, eta2);
  fmt::print("  EDMD elastic collision frequency nu = {:.5f} per unit time (Enskog with "
             "Carnahan-Starling: {:.5f})\n",
             nu, granular::enskog_collision_frequency(3, eta2, chi));
  const MeanSe cd = ds.cooling_per_collision(), cm = md.cooling_per_collision();
  const MeanSe td = ds.haff_t0(), tm = md.haff_t0();
  const double cool_sonine =
      granular::cooling_rate(alpha2, 3, a2s) / granular::collision_frequency_ratio(a2s);
  fmt::print("  engine  t_end (T0 coll. times)  T_end/T0    cooling per collision   Haff t0\n");
  fmt::print("  DSMC    {:8.1f}               {:.3e}   {:.5f} +- {:.5f}     {:.3f} +- {:.3f}\n",
             ds.t.back(), ds.T.back(), cd.mean, cd.se, td.mean, td.se);
  fmt::print("  EDMD    {:8.1f}               {:.3e}   {:.5f} +- {:.5f}     {:.3f} +- {:.3f}\n",
             md.t.back(), md.T.back(), cm.mean, cm.se, tm.mean, tm.se);
  fmt::print("  Sonine                                      {:.5f}                {:.3f}\n",
             cool_sonine, t0_sonine);
  // Check 2: the two engines' cooling per collision within 4 combined standard errors
  // (8 blocks each, Welch's t with about 14 degrees of freedom: a false failure has
  // probability P(|t_14| > 4) = 0.13 %).
  {
    const double se = std::hypot(cd.se, cm.se);
    const bool pass = std::abs(cd.mean - cm.mean) < 4.0 * se;
    fmt::print("  check: |DSMC - EDMD| cooling per collision = {:.5f} < 4 x {:.5f}: {}\n",
               std::abs(cd.mean - cm.mean), se, pass ? "yes" : "NO");
    ok = ok && pass;
  }
  // Check 3: DSMC's t0 within 2 % + 4 standard errors of the Sonine t0. The 2 % cover the
  // Sonine approximation (zeta changes by 3/16 of the error of a2, and by a3/64).
  {
    const bool pass = std::abs(td.mean - t0_sonine) < 0.02 * t0_sonine + 4.0 * td.se;
    fmt::print("  check: |DSMC t0 - Sonine t0| = {:.3f} < 2 % + 4 x {:.3f}: {}\n",
               std::abs(td.mean - t0_sonine), td.se, pass ? "yes" : "NO");
    ok = ok && pass;
  }
  {
    std::vector<std::vector<double>> rows;
    for (const auto& [engine, c] : {std::pair{0.0, &ds}, std::pair{1.0, &md}})
      for (std::size_t i = 0; i < c->t.size(); ++i)
        rows.push_back({engine, c->t[i], c->T[i], c->cpp[i], c->a2[i],
                        granular::haff_temperature_ratio(c->t[i], t0_sonine)});
    analysis::write_csv("haff.csv",
                        {"engine", "t", "T_over_T0", "collisions_per_particle", "a2", "haff_sonine"},
                        rows);
  }
  fmt::print("  ({:.1f} s)\n\n", wall());

  // ---- Part 3: clustering of inelastic disks (2D EDMD) ----------------------------------
  const double alpha3 = 0.8, eta3 = 0.25;
  const std::size_t n3 = short_run ? 2000 : 40000;
  const double c_end = short_run ? 40.0 : 800.0;  // collisions per particle after the quench
  const std::array<double, 4> snap_at = short_run ? std::array<double, 4>{0, 10, 20, 40}
                                                  : std::array<double, 4>{0, 40, 150, 800};
  const double c_row = short_run ? 5.0 : 10.0;
  edmd::Config cfg;
  cfg.n = n3;
  cfg.packing = eta3;
  cfg.seed = 17;
  edmd::Engine<2> e(cfg);
  // elastic equilibration: 20 collisions per particle; nu over its second half
  const double nu_guess =
      granular::enskog_collision_frequency(2, eta3, granular::chi_henderson(eta3));
  e.run_until(10.0 / nu_guess);
  e.reset_observables();
  e.run_until(20.0 / nu_guess);
  const double nu3 = e.collision_rate(), t_q = e.time(), T0 = e.temperature();
  const std::uint64_t c0 = e.collisions();
  e.set_restitution(alpha3);
  const double a2_2d = granular::a2_hcs(alpha3, 2), t0_2d = granular::haff_t0(alpha3, 2, a2_2d);
  const double L = e.box_side();
  fmt::print("Part 3: clustering, 2D EDMD, N = {}, packing {}, alpha = {}, box side {:.1f} sigma\n",
             n3, eta3, alpha3, L);
  fmt::print("  elastic collision frequency nu = {:.4f} (Enskog with Henderson: {:.4f}); mean "
             "free path {:.3f} sigma: the box is {:.0f} mean free paths\n",
             nu3, nu_guess, std::sqrt(0.5 * std::numbers::pi * T0) / nu3,
             L / (std::sqrt(0.5 * std::numbers::pi * T0) / nu3));
  fmt::print("  coll/part  t (T0 coll. times)  T/T0        Haff        T/Haff  cell packing "
             "max/min      rel. sd  C(r) zero\n");
  std::vector<std::vector<double>> rows3;
  int snap = 0;
  for (double target = 0.0; target <= c_end + 1e-9; target += c_row) {
    const auto goal = c0 + static_cast<std::uint64_t>(std::llround(0.5 * target * n3));
    while (e.collisions() < goal) e.step();
    Positions p;
    e.observe(p);
    const Coarse cg = coarse_grain(p);
    const double t = (e.time() - t_q) * nu3, T = e.temperature() / T0;
    const double haff = granular::haff_temperature_ratio(t, t0_2d);
    const double cpp = 2.0 * static_cast<double>(e.collisions() - c0) / static_cast<double>(n3);
    const bool shown = short_run || target <= 60.0 || std::fmod(target, 100.0) < 1e-9 ||
                       std::find(snap_at.begin(), snap_at.end(), target) != snap_at.end();
    if (shown)
      fmt::print("  {:7.1f}    {:12.1f}        {:.3e}   {:.3e}   {:6.2f}  {:.3f} / {:.3f}  "
               "{:6.3f}  {:5.1f}\n",
               cpp, t, T, haff, T / haff, cg.max, cg.min, cg.rel_sd, cg.zero);
    rows3.push_back({cpp, t, T, haff, cg.max, cg.min, cg.rel_sd, cg.zero,
                     static_cast<double>(e.tc_elastic_collisions())});
    if (snap < 4 && target >= snap_at[snap] - 1e-9) {
      const std::vector<double> rho = local_packing(p);
      std::vector<std::vector<double>> rows;
      for (std::size_t i = 0; i < rho.size(); ++i)
        rows.push_back({p.xy[2 * i], p.xy[2 * i + 1], rho[i], cpp});
      analysis::write_csv(fmt::format("snapshot_{}.csv", ++snap),
                          {"x", "y", "density", "collisions_per_particle"}, rows);
    }
  }
  analysis::write_csv("clustering.csv",
                      {"collisions_per_particle", "t", "T_over_T0", "haff_sonine",
                       "cell_packing_max", "cell_packing_min", "cell_packing_rel_sd",
                       "correlation_zero", "tc_elastic_collisions"},
                      rows3);
  fmt::print("  box side {:.1f}; coarse cells {:.2f} sigma; TC-elastic collisions {} of {} ({:.2e})\n",
             L, L / std::max(2.0, std::round(L / 10.0)), e.tc_elastic_collisions(),
             e.collisions() - c0,
             static_cast<double>(e.tc_elastic_collisions()) / static_cast<double>(e.collisions() - c0));

  fmt::print("\n{:.1f} s\n", wall());
  fmt::print("{}\n", ok ? "as expected" : "UNEXPECTED: see the checks above");
  return ok ? 0 : 1;
}
