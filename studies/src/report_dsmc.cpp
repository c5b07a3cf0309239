// The DSMC parts of the work-precision study (report.hpp): the statistical error at
// equilibrium, the finite-N bias, the Maxwell-molecule rate, the NTC step bias, the lanes
// scheme's bias and the choice of scheme.
//
// Exact finite-N equilibrium. At zero momentum and fixed energy the equilibrium of the
// Kac process is uniform on the energy sphere in the n = D (N - 1) dimensional space of
// mass-weighted, momentum-free velocities (the microcanonical ensemble). With y_i =
// sqrt(m_i) v_i = A_i z, A_i A_i^T = (1 - m_i / M) I_D (M the total mass), |z|^2 = R^2 =
// D (N - 1) kT, and E|P z|^4 = R^4 D (D + 2) / (n (n + 2)) for a D-dim projection P:
//   Q_N = D (D + 2) n / (n + 2) (1/N) sum_i (1 - m_i / M)^2,
// so Q_N / Q_inf - 1 = -(2 + 2/D) / N + O(1/N^2) for equal masses.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <cstdint>
#include <cstdio>
#include <tuple>
#include <utility>
#include <vector>

#include "clock.hpp"
#include "hypergas/analysis/estimates.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/engines.hpp"  // the engines, compiled once (extern)
#include "hypergas/dsmc/maxwell_theory.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/studies/replicas.hpp"
#include "report_parts.hpp"

namespace hypergas::studies::detail {

using analysis::MeanSe;
using analysis::mean_se;

namespace {

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
  std::vector<std::vector<double>*> results{&qx};  // what a replica writes, for a spread
  for (std::size_t k = 0; k < Ts.size(); ++k) results.insert(results.end(), {&out.est[k], &out.cpu[k]});
  for_each_replica(R, threads, [&](int r) {
    dsmc::Config cfg;
    cfg.n = N;
    cfg.init = InitialState::maxwell;
    cfg.initial.mass_ratio = 3.0;
    cfg.seed = replica_seed(seed, r);
    dsmc::Engine<D, dsmc::HardSpheres, F> e(cfg);
    if constexpr (D == 1) e.run_until(20.0);  // the two species start separately rescaled
    qx[r] = q_exact(e.particles());
    const double t0 = e.time(), c0 = thread_cpu_seconds();
    double sum = 0;
    long cnt = 0;
    std::size_t k = 0;
    for (long s = 1; k < Ts.size(); ++s) {
      e.run_until(t0 + 0.5 * s);
      sum += q_moment(e.particles());
      ++cnt;
      while (k < Ts.size() && 0.5 * s >= Ts[k] - 1e-9) {
        out.est[k][r] = sum / cnt;
        out.cpu[k][r] = thread_cpu_seconds() - c0;
        ++k;
      }
    }
  }, results);
  out.q_exact = mean_se(qx).mean;  // identical for all replicas (same masses and N)
  return out;
}

/// Calls f(DimTag<D>{}) for D = lo..hi (for_dim, vec.hpp).
template <class F>
void for_dims(int lo, int hi, F&& f) {
  for (int d = lo; d <= hi; ++d) for_dim(d, f);
}

constexpr int equilibrium_replicas = 32;

}  // namespace

// 1. Statistical regime: D = 1..6, exact finite-N reference.
void stat_study(const ReportOptions& o, ReportResult& res) {
  // T >= 16: well above the correlation time of Q (~3 mean collision times), where the
  // variance of a time average falls as 1/T.
  const std::vector<double> Ts = o.quick ? std::vector<double>{16, 64, 256, 1024}
                                         : std::vector<double>{16, 64, 256, 1024, 4096};
  const int Rs = equilibrium_replicas;
  for_dims(1, 6, [&](auto tag) {
    constexpr int D = decltype(tag)::value;
    const auto runs = equilibrium_runs<D>(1000, Ts, Rs, o.seed + 11 * D, o.threads);
    for (std::size_t k = 0; k < Ts.size(); ++k) {
      const auto [err, se] = rel_rms(runs.est[k], runs.q_exact);
      res.points.push_back({"stat", "dsmc", D, Ts[k], mean_se(runs.cpu[k]).mean, err, se, Rs});
    }
    add_slope(res, "stat", "dsmc", D);
  });
}

// 2. Finite-N bias: the same estimate at N = 200 (3D) against Maxwell-Boltzmann, and the
// bias against N in D = 2..6 against the exact Q_N.
void finite_n_study(const ReportOptions& o, ReportResult& res) {
  const bool q = o.quick;
  const int Rs = equilibrium_replicas;
  {
    const std::vector<double> Tn = q ? std::vector<double>{16, 64, 256, 1024}
                                     : std::vector<double>{16, 64, 256, 1024, 4096};
    const auto runs = equilibrium_runs<3>(200, Tn, Rs, o.seed + 500, o.threads);
    for (std::size_t k = 0; k < Tn.size(); ++k) {
      const auto [err, se] = rel_rms(runs.est[k], 15.0);
      res.points.push_back({"finite_n", "dsmc", 3, Tn[k], mean_se(runs.cpu[k]).mean, err, se, Rs});
    }
  }
  const std::vector<std::size_t> Ns = q ? std::vector<std::size_t>{8, 32}
                                        : std::vector<std::size_t>{8, 16, 32, 64};
  for_dims(2, 6, [&](auto tag) {
    constexpr int D = decltype(tag)::value;
    for (std::size_t N : Ns) {
      const double T = q ? 1000.0 : 4000.0;
      const auto runs = equilibrium_runs<D>(N, {T}, 8, o.seed + 700 + N + D, o.threads);
      const double mb = D * (D + 2.0);
      std::vector<double> rel(runs.est[0].size());
      for (std::size_t r = 0; r < rel.size(); ++r) rel[r] = runs.est[0][r] / mb - 1.0;
      const MeanSe b = mean_se(rel);
      res.finite_n.push_back({D, static_cast<double>(N), b.mean, b.se, runs.q_exact / mb - 1.0});
    }
  });
}

// 3. Maxwell molecules: the m4 relaxation rate against (D - 1)/(2D), D = 2..6.
void maxwell_study(const ReportOptions& o, ReportResult& res) {
  const std::vector<std::size_t> Nm = o.quick
                                          ? std::vector<std::size_t>{2000, 8000, 32000}
                                          : std::vector<std::size_t>{2000, 8000, 32000, 128000};
  const int Rm = o.quick ? 16 : 24;
  for_dims(2, 6, [&](auto tag) {
    constexpr int D = decltype(tag)::value;
    const double lam = dsmc::maxwell_m4_rate(D);
    for (std::size_t N : Nm) {
      std::vector<double> rate(Rm), cpu(Rm);
      for_each_replica(Rm, o.threads, [&](int r) {
        const double c0 = thread_cpu_seconds();
        dsmc::Config cfg;
        cfg.n = N;
        cfg.init = InitialState::delta;
        cfg.seed = replica_seed(o.seed + 900 + N + D, r);
        dsmc::Engine<D, dsmc::MaxwellMolecules> e(cfg);
        const auto& p = e.particles();
        double m2 = 0;
        for (std::size_t i = 0; i < N; ++i) m2 += p.velocity(i).squaredNorm();
        m2 /= N;
        // Exact finite-N equilibrium <|v|^4> (file comment, equal masses), kT from m2.
        const double kT = m2 * N / (D * (N - 1.0));
        const double m4eq = q_exact(p) * kT * kT;
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
        rate[r] = fit_decay_rate(ts, ys, 0.1 * lam, 10.0 * lam);
        cpu[r] = thread_cpu_seconds() - c0;
      }, {&rate, &cpu});
      const auto [err, se] = rel_rms(rate, lam);
      res.points.push_back(
          {"maxwell", "dsmc", D, static_cast<double>(N), mean_se(cpu).mean, err, se, Rm});
    }
    add_slope(res, "maxwell", "dsmc", D);
  });
}

namespace {
/// The kurtosis <v^4>/<v^2>^2 at t = 2 from the delta shell, 3D hard spheres, N particles,
/// of each of Rn replicas of `cfg` (seeds from sd), with each replica's thread-CPU seconds
/// (construction included).
std::pair<std::vector<double>, std::vector<double>> kurtosis_runs(const ReportOptions& o, int Rn,
                                                                  dsmc::Config cfg,
                                                                  std::uint64_t sd,
                                                                  std::size_t N) {
  std::vector<double> k(Rn), cpu(Rn);
  for_each_replica(Rn, o.threads, [&](int r) {
    dsmc::Config c = cfg;
    c.n = N;
    c.init = InitialState::delta;
    c.seed = replica_seed(sd, r);
    const Stopwatch clock(true);
    dsmc::Engine<3, dsmc::HardSpheres> e(c);
    e.run_until(2.0);
    cpu[r] = clock.seconds();
    const auto& p = e.particles();
    double m2 = 0, m4 = 0;
    for (std::size_t i = 0; i < N; ++i) m2 += p.velocity(i).squaredNorm() / N;
    for (std::size_t i = 0; i < N; ++i) m4 += std::pow(p.velocity(i).squaredNorm() / m2, 2) / N;
    k[r] = m4;
  }, {&k, &cpu});
  return {k, cpu};
}

/// kurtosis_runs at N = 10000: the mean kurtosis and the mean CPU seconds per replica.
std::pair<MeanSe, double> kurtosis_at_2(const ReportOptions& o, int Rn, dsmc::Config cfg,
                                        std::uint64_t sd) {
  const auto [k, cpu] = kurtosis_runs(o, Rn, cfg, sd, 10000);
  return {mean_se(k), mean_se(cpu).mean};
}
}  // namespace

// 4. NTC step bias in 3D: kurtosis at t = 2 from the delta shell, NTC minus exact.
void ntc_study(const ReportOptions& o, ReportResult& res) {
  const int Rn = o.quick ? 64 : 384;
  dsmc::Config exact;
  const auto [ex, ex_cpu] = kurtosis_at_2(o, Rn, exact, o.seed + 1234);
  res.exact_kurtosis = ex;
  res.exact_run_s = ex_cpu;
  std::vector<double> lx, ly;
  for (double dt : {2.0, 1.0, 0.5, 0.25, 0.125}) {
    dsmc::Config c;
    c.scheme = dsmc::Scheme::ntc;
    c.dt = dt;
    const MeanSe nt =
        kurtosis_at_2(o, Rn, c, o.seed + 2000 + static_cast<std::uint64_t>(dt * 64)).first;
    const double b = nt.mean - ex.mean;
    const double se = std::hypot(nt.se, ex.se);
    res.ntc.push_back({3, dt, b / ex.mean, se / ex.mean, 0.0});
    if (std::abs(b) > 3.0 * se) lx.push_back(std::log10(dt)), ly.push_back(std::log10(std::abs(b)));
  }
  if (lx.size() >= 2) std::tie(res.ntc_order, res.ntc_order_se) = fit_line(lx, ly);
}

// 5. The lanes scheme in 3D: the same kurtosis for lane sizes M (default epoch), minus the
// exact scheme's (ntc_study's replicas), with the CPU time per replica: bias and speed.
void lanes_study(const ReportOptions& o, ReportResult& res) {
  const int Rn = o.quick ? 64 : 384;
  for (std::uint32_t m : {8u, 64u, 512u, 4096u}) {
    dsmc::Config c;
    c.scheme = dsmc::Scheme::lanes;
    c.lane_size = m;
    const auto [la, cpu] = kurtosis_at_2(o, Rn, c, o.seed + 3000 + m);
    const MeanSe& ex = res.exact_kurtosis;
    const double b = la.mean - ex.mean;
    res.lanes.push_back({3, double(m), b / ex.mean, std::hypot(la.se, ex.se) / ex.mean, 0.0});
    res.lanes_run_s.push_back(cpu);
  }
}

// 6. The choice of scheme: one run's error of the kurtosis at t = 2 against its run time,
// exact, NTC (dt = 2, 0.5) and lanes at N = 1e4, 1e5, 1e6 (report.hpp, schemes).
void schemes_study(const ReportOptions& o, ReportResult& res) {
  struct Case {
    const char* scheme;
    dsmc::Scheme s;
    double dt;
  };
  const Case cases[] = {{"exact", dsmc::Scheme::exact, 0.0},
                        {"ntc", dsmc::Scheme::ntc, 2.0},
                        {"ntc", dsmc::Scheme::ntc, 0.5},
                        {"lanes", dsmc::Scheme::lanes, 0.0}};
  const std::size_t Ns[] = {10000, 100000, 1000000};
  const int Rs[] = {o.quick ? 16 : 64, o.quick ? 8 : 24, o.quick ? 6 : 12};
  struct Runs {
    std::vector<double> k, cpu;
  };
  std::vector<Runs> runs;  // [case][N]
  std::uint64_t sd = o.seed + 5000;
  for (const Case& c : cases)
    for (std::size_t j = 0; j < std::size(Ns); ++j) {
      dsmc::Config cfg;
      cfg.scheme = c.s;
      if (c.s == dsmc::Scheme::ntc) cfg.dt = c.dt;
      auto [k, cpu] = kurtosis_runs(o, Rs[j], cfg, sd += 97, Ns[j]);
      runs.push_back({std::move(k), std::move(cpu)});
    }
  const std::size_t ref_index = std::size(Ns) - 1;  // exact (case 0) at the largest N
  const MeanSe ref = mean_se(runs[ref_index].k);
  res.scheme_reference = ref;
  for (std::size_t c = 0; c < std::size(cases); ++c)
    for (std::size_t j = 0; j < std::size(Ns); ++j) {
      const std::size_t idx = c * std::size(Ns) + j;
      std::vector<double> rel = runs[idx].k;
      for (double& v : rel) v = v / ref.mean - 1.0;
      const MeanSe m = mean_se(rel);
      const double R = static_cast<double>(rel.size());
      double var = 0;
      for (double v : rel) var += (v - m.mean) * (v - m.mean);
      var /= R - 1.0;
      // The bias and its noise: the point's mean and the reference's (none for the
      // reference itself, whose bias is 0 by definition).
      const double ref_se = ref.se / ref.mean;
      const double se_b2 = idx == ref_index ? 0.0 : m.se * m.se + ref_se * ref_se;
      const double b = idx == ref_index ? 0.0 : m.mean;
      const double b2 = std::max(0.0, b * b - se_b2);
      const double err = std::sqrt(var + b2);
      const double var_err =
          (var * var / (2.0 * (R - 1.0)) + (4.0 * b * b * se_b2 + 2.0 * se_b2 * se_b2) / 4.0) /
          (err * err);
      res.schemes.push_back({cases[c].scheme, cases[c].dt, static_cast<double>(Ns[j]),
                             mean_se(runs[idx].cpu).mean, err, std::sqrt(var_err),
                             static_cast<int>(R)});
    }
}

}  // namespace hypergas::studies::detail
