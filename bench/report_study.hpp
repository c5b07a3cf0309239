// bench/report_study.hpp -- error against run time (work-precision study), reusable by
// `hypergas report` and bench/bench_report.cpp.
//
//   hypergas::bench::ReportOptions o;  o.out = "report"; o.quick = true;
//   int rc = hypergas::bench::run_report(o);   // writes CSVs + work_precision.png in o.out
//
// Every error is measured against an exact value, never against another run of the code:
//   stat        DSMC hard spheres at equilibrium, D = 1..6: the time average of
//               Q = <(m |v|^2 / kT)^2> over a run of length T, against its exact
//               finite-N value (below). Run time grows with T; the RMS error over replicas
//               falls as (run time)^(-1/2): the statistical regime.
//   finite_n    the same estimate for N = 200 in 3D against the Maxwell-Boltzmann value
//               D (D + 2) (<v^4> = D (D+2) (kT/m)^2): the error levels off at the finite-N
//               bias. finite_n.csv lists the bias against N for D = 2..6 with the exact
//               prediction below (slope -1 in N).
//   maxwell     Maxwell molecules, D = 2..6: the relaxation rate of <|v|^4> from the delta
//               shell, fitted over 3 e-folds, against the exact (D - 1)/(2D)
//               (dsmc/maxwell_theory.hpp); run time grows with N.
//   ntc         Bird's NTC scheme, 3D hard spheres: the kurtosis <v^4>/<v^2>^2 at t = 2 from
//               the delta shell for steps dt, minus the exact scheme's value (the time-
//               continuous process; no closed form exists for hard spheres), in ntc.csv; the
//               order p of |bias| ~ dt^p is fitted where the bias exceeds 3 standard errors.
//   eos         EDMD, N = 1000, D = 1..4: the reduced pressure Z from the collision virial
//               over a window of T time units (after the lattice has melted, t = 2), against
//                 1D rods, eta = 0.5: Tonks' exact Z = 1/(1 - eta) (L. Tonks, Phys. Rev. 50,
//                    955 (1936)); exact for any N with kT = 2 E_kin/N, so no floor. Equal
//                    rods only exchange velocities: the gas is N free points in the free
//                    length L - N sigma (integrable), the collision count of a window is
//                    fixed up to end effects, which add a 1/T term: the error falls at
//                    least as fast as T^(-1/2) (slopes -0.6 to -0.8 measured);
//                 2D disks, eta = 0.3: Henderson's Z = (1 + eta^2/8)/(1 - eta)^2 (Mol. Phys.
//                    30, 971 (1975); ~2e-3 from simulation);
//                 3D, eta = 0.2618: Carnahan-Starling (J. Chem. Phys. 51, 635 (1969); within
//                    ~1e-3 of simulation here). At N = 1000 this code gives Z = 3.270-3.274
//                    (six runs of 50 time units, se 0.0015), at N = 1e6 3.2686, against CS
//                    3.2624: a floor of ~3e-3 from the finite-N bias plus CS's own error;
//                 4D, x = B2 rho = 0.2 (eta = 0.025): the virial series 1 + x + (B3/B2^2) x^2,
//                    B3/B2^2 = 4/3 - 3 sqrt(3)/(2 pi) (Luban & Baram, J. Chem. Phys. 76, 3233
//                    (1982)); truncation < 0.0027 (Clisby & McCoy, J. Stat. Phys. 122, 15
//                    (2006)), a floor of ~2e-3 relative.
//               Relative RMS error over replicas; it falls as (run time)^(-1/2) until such a
//               floor. The slope is fitted over the statistical part, windows T <= 4.
//
// Exact finite-N equilibrium. At zero momentum and fixed energy the equilibrium of the
// Kac process is uniform on the energy sphere in the n = D (N - 1) dimensional space of
// mass-weighted, momentum-free velocities (the microcanonical ensemble). With y_i =
// sqrt(m_i) v_i = A_i z, A_i A_i^T = (1 - m_i / M) I_D (M the total mass), |z|^2 = R^2 =
// D (N - 1) kT, and E|P z|^4 = R^4 D (D + 2) / (n (n + 2)) for a D-dim projection P:
//   Q_N = D (D + 2) n / (n + 2) (1/N) sum_i (1 - m_i / M)^2,
// so Q_N / Q_inf - 1 = -(2 + 2/D) / N + O(1/N^2) for equal masses.
//
// Run time is the CPU time of the thread that runs the replica (CLOCK_THREAD_CPUTIME_ID):
// on an idle core it equals wall-clock time, and on a shared machine it does not count the
// time the thread waited, so slopes stay meaningful. Slopes are least-squares fits of
// log10(error) against log10(run time), with their standard errors.
#pragma once

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "hypergas/dsmc/engine.hpp"
#include "hypergas/dsmc/maxwell_theory.hpp"
#include "hypergas/dsmc/replicas.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/edmd/observables.hpp"
#include "hypergas/error.hpp"
#include "report_plot.hpp"

namespace hypergas::bench {

/// What `run_report` computes and where it writes.
struct ReportOptions {
  std::string out = "report";  ///< output folder (created if missing; files replaced)
  bool quick = false;          ///< ~20 s instead of ~5 min: fewer points and replicas
  std::uint64_t seed = 1;      ///< all randomness derives from it
  int threads = 2;             ///< replicas run on this many threads (1..64)
  bool plot = true;            ///< run gnuplot (if on PATH) to write work_precision.png
  bool verbose = true;         ///< one progress line per study on stderr
};

/// One point of a work-precision curve: relative error (RMS over replicas) of `study`
/// at control parameter `param` (run length T, N or dt), mean run time per replica (s).
struct ReportPoint {
  std::string study, engine;
  int dim = 0;
  double param = 0.0, run_s = 0.0, error = 0.0, error_se = 0.0;
  int replicas = 0;
};

/// Least-squares slope of log10(error) against log10(x) for one curve.
struct ReportSlope {
  std::string study, engine;
  int dim = 0;
  double slope = 0.0, slope_se = 0.0;
  int points = 0;
};

/// One row of a bias table (finite-N bias against N, NTC bias against dt).
struct BiasRow {
  int dim = 0;
  double param = 0.0, bias = 0.0, bias_se = 0.0, theory = 0.0;
};

/// Everything the report computes.
struct ReportResult {
  std::vector<ReportPoint> points;
  std::vector<ReportSlope> slopes;
  std::vector<BiasRow> finite_n, ntc;
  double ntc_order = std::numeric_limits<double>::quiet_NaN();  ///< p in |bias| ~ dt^p
  double ntc_order_se = std::numeric_limits<double>::quiet_NaN();
  double total_s = 0.0;  ///< wall-clock seconds of the whole study
};

namespace detail {

/// CPU seconds used by the calling thread.
inline double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// Runs f(r) for r = 0..R-1 on `threads` threads (replica r on thread r mod threads).
template <class Fn>
void parallel_replicas(int R, int threads, Fn&& f) {
  threads = std::max(1, std::min(threads, R));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (int r = t; r < R; r += threads) f(r);
    });
  for (int r = 0; r < R; r += threads) f(r);
  for (auto& th : pool) th.join();
}

/// Least-squares line y = a + b x: returns {b, standard error of b}.
inline std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  double sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  const double b = sxy / sxx;
  double rss = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double e = y[k] - my - b * (x[k] - mx);
    rss += e * e;
  }
  const double se = x.size() > 2 ? std::sqrt(rss / (n - 2.0) / sxx) : std::nan("");
  return {b, se};
}

/// Rate lambda of the least-squares fit y_k = A exp(-lambda t_k) (A eliminated exactly,
/// golden-section search on [lo, hi]).
inline double fit_decay_rate(const std::vector<double>& t, const std::vector<double>& y, double lo,
                             double hi) {
  auto resid = [&](double lam) {
    double se = 0, sye = 0, syy = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double e = std::exp(-lam * t[k]);
      se += e * e, sye += y[k] * e, syy += y[k] * y[k];
    }
    return syy - sye * sye / se;
  };
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo, b = hi, c = b - g * (b - a), d = a + g * (b - a);
  for (int it = 0; it < 100; ++it) {
    if (resid(c) < resid(d)) b = d;
    else a = c;
    c = b - g * (b - a), d = a + g * (b - a);
  }
  return 0.5 * (a + b);
}

/// Q = (1/N) sum (m |v|^2 / kT)^2 with kT = sum m |v|^2 / (D (N - 1)) (squares of
/// normalised values only: safe at any velocity scale).
template <int D, Features F>
double q_moment(const Particles<D, F>& p) {
  double e2 = 0;
  for (std::size_t i = 0; i < p.size(); ++i) e2 += p.velocity(i).squaredNorm() / p.inv_mass(i);
  const double kT = e2 / (D * (static_cast<double>(p.size()) - 1.0));
  double q = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.velocity(i).squaredNorm() / (p.inv_mass(i) * kT);
    q += x * x;
  }
  return q / static_cast<double>(p.size());
}

/// Exact microcanonical Q_N (file comment) for the particles' masses.
template <int D, Features F>
double q_exact(const Particles<D, F>& p) {
  const double N = static_cast<double>(p.size()), n = D * (N - 1.0);
  double M = 0, s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) M += 1.0 / p.inv_mass(i);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double f = 1.0 - 1.0 / (p.inv_mass(i) * M);
    s += f * f;
  }
  return D * (D + 2.0) * n / (n + 2.0) * s / N;
}

/// Relative RMS of (x_r - ref)/ref over replicas and its standard error (~ rms / sqrt(2R)).
inline std::pair<double, double> rel_rms(const std::vector<double>& x, double ref) {
  double s = 0;
  for (double v : x) s += (v - ref) * (v - ref);
  const double rms = std::sqrt(s / static_cast<double>(x.size())) / std::abs(ref);
  return {rms, rms / std::sqrt(2.0 * static_cast<double>(x.size()))};
}

inline double mean(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}
inline double std_error(const std::vector<double>& x) {
  const double m = mean(x);
  double s = 0;
  for (double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / (static_cast<double>(x.size()) - 1.0) / static_cast<double>(x.size()));
}

/// Equilibrium runs: for each replica, the time average of Q over [0, T_k] (samples every
/// 0.5 mean collision times) and the CPU seconds spent to reach T_k; also Q_N of each run.
/// D = 1 uses two species (masses 1 and 3) and a warm-up: equal masses never relax in 1D.
struct EqRuns {
  std::vector<std::vector<double>> est, cpu;  // [k][replica]
  double q_exact = 0.0;
};
template <int D>
EqRuns equilibrium_runs(std::size_t N, const std::vector<double>& Ts, int R, std::uint64_t seed,
                        int threads) {
  constexpr Features F{.species = (D == 1)};
  EqRuns out;
  out.est.assign(Ts.size(), std::vector<double>(R));
  out.cpu = out.est;
  std::vector<double> qx(R);
  parallel_replicas(R, threads, [&](int r) {
    dsmc::Config cfg;
    cfg.n = N;
    cfg.initial.mass_ratio = 3.0;
    cfg.seed = dsmc::replica_seed(seed, r);
    dsmc::Engine<D, dsmc::HardSpheres, F> e(cfg);
    if constexpr (D == 1) e.run_until(20.0);  // the two species start separately rescaled
    qx[r] = q_exact(e.particles());
    const double t0 = e.time(), c0 = thread_cpu_s();
    double sum = 0;
    long cnt = 0;
    std::size_t k = 0;
    for (long s = 1; k < Ts.size(); ++s) {
      e.run_until(t0 + 0.5 * s);
      sum += q_moment(e.particles());
      ++cnt;
      while (k < Ts.size() && 0.5 * s >= Ts[k] - 1e-9) {
        out.est[k][r] = sum / cnt;
        out.cpu[k][r] = thread_cpu_s() - c0;
        ++k;
      }
    }
  });
  out.q_exact = mean(qx);  // identical for all replicas (same masses and N)
  return out;
}

template <class Fn>
void for_dims(int lo, int hi, Fn&& f) {
  auto one = [&](auto tag) {
    if (decltype(tag)::value >= lo && decltype(tag)::value <= hi) f(tag);
  };
  one(DimTag<1>{}), one(DimTag<2>{}), one(DimTag<3>{}), one(DimTag<4>{}), one(DimTag<5>{}),
      one(DimTag<6>{});
}

/// Fits the slope of one curve, over its points with param <= max_param.
inline void add_slope(ReportResult& res, const std::string& study, const std::string& engine,
                      int dim, double max_param = std::numeric_limits<double>::infinity()) {
  std::vector<double> x, y;
  for (const auto& p : res.points)
    if (p.study == study && p.engine == engine && p.dim == dim && p.error > 0 &&
        p.param <= max_param) {
      x.push_back(std::log10(p.run_s));
      y.push_back(std::log10(p.error));
    }
  if (x.size() < 2) return;
  const auto [b, se] = fit_line(x, y);
  res.slopes.push_back({study, engine, dim, b, se, static_cast<int>(x.size())});
}

/// Packing fraction and reference Z of the EDMD study in dimension D (file comment).
inline std::pair<double, double> eos_reference(int D) {
  switch (D) {
    case 1: return {0.5, 1.0 / (1.0 - 0.5)};         // Tonks: exact
    case 2: return {0.3, edmd::henderson_Z(0.3)};    // Henderson
    case 3: return {0.2618, edmd::carnahan_starling_Z(0.2618)};
    default: {                                       // 4D: virial series to B3
      const double x = 0.2, b3 = 4.0 / 3.0 - 3.0 * std::sqrt(3.0) / (2.0 * std::numbers::pi);
      return {x / 8.0, 1.0 + x + b3 * x * x};
    }
  }
}

}  // namespace detail

/// Runs the studies of the file comment and returns their results (nothing is written).
/// Throws InvalidInput for bad options.
inline ReportResult run_report_study(const ReportOptions& o) {
  if (o.threads < 1 || o.threads > 64) throw InvalidInput("report: threads must be in 1..64");
  const auto wall0 = std::chrono::steady_clock::now();
  auto say = [&](const std::string& s) {
    if (o.verbose) std::fprintf(stderr, "report: %s\n", s.c_str());
  };
  ReportResult res;
  const bool q = o.quick;

  // 1. Statistical regime: D = 1..6, exact finite-N reference.
  say("statistical error of the equilibrium <(m v^2/kT)^2>, D = 1..6");
  // T >= 16: well above the correlation time of Q (~3 mean collision times), where the
  // variance of a time average falls as 1/T.
  const std::vector<double> Ts = q ? std::vector<double>{16, 64, 256, 1024}
                                   : std::vector<double>{16, 64, 256, 1024, 4096};
  const int Rs = 32;
  detail::for_dims(1, 6, [&](auto tag) {
    constexpr int D = decltype(tag)::value;
    const auto runs = detail::equilibrium_runs<D>(1000, Ts, Rs, o.seed + 11 * D, o.threads);
    for (std::size_t k = 0; k < Ts.size(); ++k) {
      const auto [err, se] = detail::rel_rms(runs.est[k], runs.q_exact);
      res.points.push_back({"stat", "dsmc", D, Ts[k], detail::mean(runs.cpu[k]), err, se, Rs});
    }
    detail::add_slope(res, "stat", "dsmc", D);
  });

  // 2. Finite-N bias: the same estimate at N = 16 (3D) against Maxwell-Boltzmann.
  say("finite-N bias: N = 200 in 3D against Maxwell-Boltzmann, and bias against N");
  {
    const std::vector<double> Tn = q ? std::vector<double>{16, 64, 256, 1024}
                                     : std::vector<double>{16, 64, 256, 1024, 4096};
    const auto runs = detail::equilibrium_runs<3>(200, Tn, Rs, o.seed + 500, o.threads);
    for (std::size_t k = 0; k < Tn.size(); ++k) {
      const auto [err, se] = detail::rel_rms(runs.est[k], 15.0);
      res.points.push_back({"finite_n", "dsmc", 3, Tn[k], detail::mean(runs.cpu[k]), err, se, Rs});
    }
  }
  const std::vector<std::size_t> Ns = q ? std::vector<std::size_t>{8, 32}
                                        : std::vector<std::size_t>{8, 16, 32, 64};
  detail::for_dims(2, 6, [&](auto tag) {
    constexpr int D = decltype(tag)::value;
    for (std::size_t N : Ns) {
      const double T = q ? 1000.0 : 4000.0;
      const auto runs = detail::equilibrium_runs<D>(N, {T}, 8, o.seed + 700 + N + D, o.threads);
      const double mb = D * (D + 2.0);
      std::vector<double> rel(runs.est[0].size());
      for (std::size_t r = 0; r < rel.size(); ++r) rel[r] = runs.est[0][r] / mb - 1.0;
      res.finite_n.push_back({D, static_cast<double>(N), detail::mean(rel), detail::std_error(rel),
                              runs.q_exact / mb - 1.0});
    }
  });

  // 3. Maxwell molecules: the m4 relaxation rate against (D - 1)/(2D), D = 2..6.
  say("Maxwell-molecule fourth-moment rate, D = 2..6");
  const std::vector<std::size_t> Nm = q ? std::vector<std::size_t>{2000, 8000, 32000}
                                        : std::vector<std::size_t>{2000, 8000, 32000, 128000};
  const int Rm = q ? 16 : 24;
  detail::for_dims(2, 6, [&](auto tag) {
    constexpr int D = decltype(tag)::value;
    const double lam = dsmc::maxwell_m4_rate(D);
    for (std::size_t N : Nm) {
      std::vector<double> rate(Rm), cpu(Rm);
      detail::parallel_replicas(Rm, o.threads, [&](int r) {
        const double c0 = detail::thread_cpu_s();
        dsmc::Config cfg;
        cfg.n = N;
        cfg.model = dsmc::ModelKind::maxwell;
        cfg.init = InitialState::delta;
        cfg.seed = dsmc::replica_seed(o.seed + 900 + N + D, r);
        dsmc::Engine<D, dsmc::MaxwellMolecules> e(cfg);
        const auto& p = e.particles();
        double m2 = 0;
        for (std::size_t i = 0; i < N; ++i) m2 += p.velocity(i).squaredNorm();
        m2 /= N;
        // Exact finite-N equilibrium <|v|^4> (file comment, equal masses), kT from m2.
        const double kT = m2 * N / (D * (N - 1.0));
        const double m4eq = detail::q_exact(p) * kT * kT;
        std::vector<double> ts, ys;
        const int K = 30;
        for (int k = 0; k <= K; ++k) {
          const double t = 3.0 / lam * k / K;
          e.run_until(t);
          double m4 = 0;
          for (std::size_t i = 0; i < N; ++i) m4 += std::pow(p.velocity(i).squaredNorm(), 2);
          ts.push_back(t);
          ys.push_back(m4 / N - m4eq);
        }
        rate[r] = detail::fit_decay_rate(ts, ys, 0.1 * lam, 10.0 * lam);
        cpu[r] = detail::thread_cpu_s() - c0;
      });
      const auto [err, se] = detail::rel_rms(rate, lam);
      res.points.push_back({"maxwell", "dsmc", D, static_cast<double>(N), detail::mean(cpu), err,
                            se, Rm});
    }
    detail::add_slope(res, "maxwell", "dsmc", D);
  });

  // 4. NTC step bias in 3D: kurtosis at t = 2 from the delta shell, NTC minus exact.
  say("NTC time-step bias against the exact process, 3D hard spheres");
  {
    const int Rn = q ? 64 : 384;
    const std::size_t N = 10000;
    auto kurt = [&](dsmc::Scheme s, double dt, std::uint64_t sd) {
      std::vector<double> k(Rn);
      detail::parallel_replicas(Rn, o.threads, [&](int r) {
        dsmc::Config cfg;
        cfg.n = N;
        cfg.init = InitialState::delta;
        cfg.scheme = s;
        cfg.dt = dt;
        cfg.seed = dsmc::replica_seed(sd, r);
        dsmc::Engine<3, dsmc::HardSpheres> e(cfg);
        e.run_until(2.0);
        const auto& p = e.particles();
        double m2 = 0, m4 = 0;
        for (std::size_t i = 0; i < N; ++i) m2 += p.velocity(i).squaredNorm() / N;
        for (std::size_t i = 0; i < N; ++i) m4 += std::pow(p.velocity(i).squaredNorm() / m2, 2) / N;
        k[r] = m4;
      });
      return k;
    };
    const auto ex = kurt(dsmc::Scheme::exact, 1.0, o.seed + 1234);
    const double me = detail::mean(ex), se_e = detail::std_error(ex);
    std::vector<double> lx, ly;
    for (double dt : {2.0, 1.0, 0.5, 0.25, 0.125}) {
      const auto nt = kurt(dsmc::Scheme::ntc, dt, o.seed + 2000 + static_cast<std::uint64_t>(dt * 64));
      const double b = detail::mean(nt) - me;
      const double se = std::hypot(detail::std_error(nt), se_e);
      res.ntc.push_back({3, dt, b / me, se / me, 0.0});
      if (std::abs(b) > 3.0 * se) lx.push_back(std::log10(dt)), ly.push_back(std::log10(std::abs(b)));
    }
    if (lx.size() >= 2) std::tie(res.ntc_order, res.ntc_order_se) = detail::fit_line(lx, ly);
  }

  // 5. EDMD: Z against its reference in D = 1..4; run time grows with the measurement window.
  say("EDMD pressure Z against Tonks (1D), Henderson (2D), Carnahan-Starling (3D), virial (4D)");
  {
    const std::vector<double> Te = q ? std::vector<double>{0.25, 1, 4}
                                     : std::vector<double>{0.25, 1, 4, 16, 64};
    const int Re = 16;
    for_each_dim([&](auto tag) {
      constexpr int D = decltype(tag)::value;
      if constexpr (D <= 4) {
        const auto [eta, zref] = detail::eos_reference(D);
        for (double T : Te) {
          std::vector<double> z(Re), cpu(Re);
          detail::parallel_replicas(Re, o.threads, [&](int r) {
            edmd::Config cfg;
            cfg.n = 1000;
            cfg.packing = eta;
            cfg.seed = dsmc::replica_seed(
                o.seed + 3000 + 100 * static_cast<std::uint64_t>(D) + static_cast<std::uint64_t>(T),
                r);
            edmd::Engine<D> e(cfg);
            e.run_until(2.0);  // melt the lattice start
            e.reset_observables();
            const double c0 = detail::thread_cpu_s();
            e.run_until(2.0 + T);
            cpu[r] = detail::thread_cpu_s() - c0;
            z[r] = e.pressure_Z();
          });
          const auto [err, se] = detail::rel_rms(z, zref);
          res.points.push_back({"eos", "edmd", D, T, detail::mean(cpu), err, se, Re});
        }
        detail::add_slope(res, "eos", "edmd", D, 4.0);  // statistical regime (file comment)
      }
    });
  }
  res.total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

/// Writes work_precision.csv, slopes.csv, finite_n.csv, ntc.csv (and, with plot,
/// plot_report.gp and work_precision.png) into `dir`. Each file is written to a temporary
/// name and renamed when complete. Throws InvalidInput if the folder cannot be written.
inline void write_report(const ReportResult& res, const std::filesystem::path& dir, bool plot) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InvalidInput("report: cannot create output folder " + dir.string());
  auto write = [&](const std::string& name, const std::function<void(std::FILE*)>& body) {
    const auto tmp = dir / (name + ".tmp"), fin = dir / name;
    std::FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f) throw InvalidInput("report: cannot write " + fin.string());
    body(f);
    const bool ok = std::fclose(f) == 0;
    if (!ok || std::rename(tmp.c_str(), fin.c_str()) != 0)
      throw InvalidInput("report: cannot write " + fin.string());
  };
  write("work_precision.csv", [&](std::FILE* f) {
    std::fprintf(f, "study,engine,dim,param,run_s,error,error_se,replicas\n");
    for (const auto& p : res.points)
      std::fprintf(f, "%s,%s,%d,%.10g,%.6e,%.6e,%.3e,%d\n", p.study.c_str(), p.engine.c_str(),
                   p.dim, p.param, p.run_s, p.error, p.error_se, p.replicas);
  });
  write("slopes.csv", [&](std::FILE* f) {
    std::fprintf(f, "study,engine,dim,slope,slope_se,points\n");
    for (const auto& s : res.slopes)
      std::fprintf(f, "%s,%s,%d,%.4f,%.4f,%d\n", s.study.c_str(), s.engine.c_str(), s.dim, s.slope,
                   s.slope_se, s.points);
  });
  auto bias = [&](const std::string& name, const char* param, const std::vector<BiasRow>& rows) {
    write(name, [&](std::FILE* f) {
      std::fprintf(f, "dim,%s,rel_bias,rel_bias_se,theory\n", param);
      for (const auto& b : rows)
        std::fprintf(f, "%d,%.10g,%.6e,%.3e,%.6e\n", b.dim, b.param, b.bias, b.bias_se, b.theory);
    });
  };
  bias("finite_n.csv", "n", res.finite_n);
  bias("ntc.csv", "dt", res.ntc);
  write("slopes.gp", [&](std::FILE* f) {  // slope variables for the gnuplot titles
    for (const auto& s : res.slopes)
      std::fprintf(f, "slope_%s_%s_%d = %.3f\n", s.study.c_str(), s.engine.c_str(), s.dim, s.slope);
    std::fprintf(f, "ntc_order = %.3f\n", std::isnan(res.ntc_order) ? -99.0 : res.ntc_order);
  });
  write("plot_report.gp", [&](std::FILE* f) { std::fputs(report_plot_script, f); });
  if (plot) run_report_gnuplot(dir);
}

/// The `hypergas report` entry point: runs the study, writes the files, prints a summary
/// of the slopes on stdout. Returns 0; throws InvalidInput for bad options or folders.
inline int run_report(const ReportOptions& o) {
  const ReportResult res = run_report_study(o);
  write_report(res, o.out, o.plot);
  std::printf("%-10s %-6s %3s %8s %8s\n", "study", "engine", "D", "slope", "+-");
  for (const auto& s : res.slopes)
    std::printf("%-10s %-6s %3d %8.3f %8.3f\n", s.study.c_str(), s.engine.c_str(), s.dim, s.slope,
                s.slope_se);
  if (std::isnan(res.ntc_order))
    std::printf("NTC step bias: not detectable at any dt (|bias| < 3 se), see ntc.csv\n");
  else
    std::printf("NTC step bias order: %.2f +- %.2f\n", res.ntc_order, res.ntc_order_se);
  std::printf("report written to %s in %.1f s\n", o.out.c_str(), res.total_s);
  return 0;
}

}  // namespace hypergas::bench
