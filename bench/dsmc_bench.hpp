// bench/dsmc_bench.hpp -- DSMC throughput benchmark, reusable by `hypergas bench`.
//
// For each D and N: a hard-sphere gas relaxing from the delta shell (after a warm-up of 0.5
// mean collision times) is run for at least `min_collisions` accepted collisions, `reps`
// times; the median collisions/s is reported with the acceptance ratio, the bytes per
// particle and the ratio to a memory-bound probe run in the same process: random pair
// updates (load two records of the same stride, average-and-swap their components, store)
// over an array of the same size, with the same prefetching as the engine. One JSON object
// per line on `out`. The engine is sequential (one core); with `threads` > 1 a second line
// per point reports the aggregate rate of that many independent replicas run concurrently
// (dsmc/replicas.hpp), which is how the second core is used without changing statistics.
// Rates are per wall second; with `cpu_clock`, per CPU second of the thread (bench_clock.hpp)
// for paired A/B runs on a shared machine. The JSON says which ("clock").
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "bench_clock.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/dsmc/replicas.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/rng.hpp"

namespace hypergas::bench {

/// What to measure.
struct DsmcBenchOptions {
  std::vector<int> dims = {1, 2, 3, 4, 5, 6};
  std::vector<std::size_t> ns = {10000, 1000000, 10000000};
  int reps = 3;                 ///< runs per point; the median is reported
  double min_collisions = 5e6;  ///< accepted collisions per timed run
  dsmc::ModelKind model = dsmc::ModelKind::hs;
  std::uint64_t seed = 1;
  int threads = 1;  ///< > 1: also time that many independent replicas run concurrently
  bool cpu_clock = false;  ///< rates per CPU second of the thread instead of per wall second
};

namespace detail {

inline double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  const std::size_t m = x.size() / 2;
  return x.size() % 2 ? x[m] : 0.5 * (x[m - 1] + x[m]);
}

/// Random pair updates per second on n records of `Particles<D>::stride` doubles.
template <int D>
double pair_update_probe(std::size_t n, double updates, std::uint64_t seed, bool cpu_clock) {
  Particles<D> p(n);
  double* v = p.velocity_data().data();
  constexpr int S = Particles<D>::stride;
  for (std::size_t i = 0; i < n * S; ++i) v[i] = 1e-3 * static_cast<double>(i % 1000);
  dsmc::detail::advise_huge_pages(v, n * S * sizeof(double));  // as the engine does
  Rng rng(seed, 99);
  constexpr int ring = 32;
  std::uint32_t ri[ring], rj[ring];
  auto draw = [&](int k) {
    ri[k] = static_cast<std::uint32_t>(rng.below(n));
    rj[k] = static_cast<std::uint32_t>(rng.below(n));
    __builtin_prefetch(v + std::size_t(ri[k]) * S, 1);
    __builtin_prefetch(v + std::size_t(rj[k]) * S, 1);
  };
  for (int k = 0; k < ring; ++k) draw(k);
  const auto m = static_cast<std::uint64_t>(updates);
  const Stopwatch clock(cpu_clock);
  for (std::uint64_t c = 0; c < m; ++c) {
    const int k = static_cast<int>(c % ring);
    double* a = v + std::size_t(ri[k]) * S;
    double* b = v + std::size_t(rj[k]) * S;
    draw(k);
    for (int d = 0; d < D; ++d) {
      const double s = 0.5 * (a[d] + b[d]), h = 0.5 * (a[d] - b[d]);
      a[d] = s - h;
      b[d] = s + h;
    }
  }
  const double w = clock.seconds();
  volatile double sink = v[0];
  (void)sink;
  return static_cast<double>(m) / w;
}

struct DsmcPoint {
  double collisions_per_s, candidates_per_s, acceptance, bytes_per_particle, wall_s;
};

template <int D, class Model>
DsmcPoint time_engine(std::size_t n, double min_collisions, std::uint64_t seed, bool cpu_clock) {
  dsmc::Config cfg;
  cfg.n = n;
  cfg.seed = seed;
  cfg.init = InitialState::delta;
  cfg.vhs_exponent = 0.5;
  dsmc::Engine<D, Model> e(cfg);
  e.run_until(0.5);
  const auto c0 = e.collisions(), k0 = e.candidates();
  const double t_run = 2.0 * min_collisions / static_cast<double>(n);
  const Stopwatch clock(cpu_clock);
  e.run_until(e.time() + t_run);
  const double w = clock.seconds();
  const double dc = static_cast<double>(e.collisions() - c0);
  const double dk = static_cast<double>(e.candidates() - k0);
  return {dc / w, dk / w, dc / dk, e.bytes_per_particle(), w};
}

template <int D>
DsmcPoint time_model(dsmc::ModelKind m, std::size_t n, double min_coll, std::uint64_t seed,
                     bool cpu) {
  switch (m) {
    case dsmc::ModelKind::maxwell:
      return time_engine<D, dsmc::MaxwellMolecules>(n, min_coll, seed, cpu);
    case dsmc::ModelKind::vhs:
      return time_engine<D, dsmc::VariableHardSpheres>(n, min_coll, seed, cpu);
    default:
      return time_engine<D, dsmc::HardSpheres>(n, min_coll, seed, cpu);
  }
}

template <int D>
void bench_point(std::ostream& out, const DsmcBenchOptions& o, std::size_t n) {
  std::vector<double> rate, cand, acc, probe;
  double bytes = 0.0;
  for (int r = 0; r < o.reps; ++r) {
    const DsmcPoint p = time_model<D>(o.model, n, o.min_collisions, o.seed + r, o.cpu_clock);
    rate.push_back(p.collisions_per_s);
    cand.push_back(p.candidates_per_s);
    acc.push_back(p.acceptance);
    bytes = p.bytes_per_particle;
    probe.push_back(
        pair_update_probe<D>(n, std::max(2e6, o.min_collisions), o.seed + r, o.cpu_clock));
  }
  const double cr = median(rate), pr = median(probe);
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "{\"bench\":\"dsmc\",\"engine\":\"dsmc\",\"model\":\"%s\",\"dim\":%d,\"n\":%zu,"
                "\"reps\":%d,\"collisions_per_s\":%.4g,\"candidates_per_s\":%.4g,"
                "\"acceptance\":%.4f,\"bytes_per_particle\":%.1f,"
                "\"probe_pair_updates_per_s\":%.4g,\"probe_ratio\":%.4f,\"threads\":1,"
                "\"clock\":\"%s\"}",
                std::string(dsmc::to_string(o.model)).c_str(), D, n, o.reps, cr, median(cand),
                median(acc), bytes, pr, cr / pr, o.cpu_clock ? "cpu" : "wall");
  out << buf << '\n' << std::flush;
  if (o.threads > 1) {  // aggregate throughput of independent replicas, one per thread
    dsmc::Config cfg;
    cfg.n = n;
    cfg.seed = o.seed;
    cfg.init = InitialState::delta;
    std::vector<double> coll(o.threads), wall(o.threads);
    dsmc::run_replicas<dsmc::Engine<D, dsmc::HardSpheres>>(
        cfg, o.threads, o.threads, [&](int r, auto& e) {
          const auto c0 = e.collisions();
          const Stopwatch clock(false);
          e.run_until(2.0 * o.min_collisions / static_cast<double>(n));
          coll[r] = static_cast<double>(e.collisions() - c0);
          wall[r] = clock.seconds();
        });
    double total = 0.0;
    for (int r = 0; r < o.threads; ++r) total += coll[r] / wall[r];
    std::snprintf(buf, sizeof buf,
                  "{\"bench\":\"dsmc_replicas\",\"engine\":\"dsmc\",\"model\":\"hs\",\"dim\":%d,"
                  "\"n\":%zu,\"threads\":%d,\"collisions_per_s\":%.4g}",
                  D, n, o.threads, total);
    out << buf << '\n' << std::flush;
  }
}

}  // namespace detail

/// Runs the DSMC throughput benchmark and prints one JSON line per (D, N) to `out`.
/// Fields: collisions_per_s (median accepted collisions per second), candidates_per_s,
/// acceptance, bytes_per_particle, probe_pair_updates_per_s, probe_ratio.
inline void run_dsmc_bench(std::ostream& out, const DsmcBenchOptions& o = {}) {
  for (std::size_t n : o.ns)
    for (int d : o.dims)
      for_each_dim([&](auto tag) {
        constexpr int D = decltype(tag)::value;
        if (D == d) detail::bench_point<D>(out, o, n);
      });
}

}  // namespace hypergas::bench
