// DSMC throughput (throughput.hpp): timed engine runs on 1..T threads, the memory-bound probe.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "clock.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/dsmc/huge_pages.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/engines.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/studies/statistics.hpp"
#include "hypergas/studies/throughput.hpp"

namespace hypergas::studies {

namespace {

using detail::Stopwatch;

/// Random pair updates per second on n records of `Particles<D>::stride` doubles.
template <int D>
double pair_update_probe(std::size_t n, double updates, std::uint64_t seed, bool cpu_clock) {
  Particles<D> p(n);
  double* v = p.velocity_data().data();
  constexpr int S = Particles<D>::stride;
  for (std::size_t i = 0; i < n * S; ++i) v[i] = 1e-3 * static_cast<double>(i % 1000);
  dsmc::advise_huge_pages(v, n * S * sizeof(double));  // as the engine does
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
  double collisions_per_s = 0.0, candidates_per_s = 0.0, acceptance = 0.0,
         bytes_per_particle = 0.0, wall_s = 0.0;
  double ticks_per_s = 0.0;                    // the phase clock's rate (TSC)
  std::vector<dsmc::PhaseTicks> schedule;      // per thread (empty on one thread)
};

/// Times an engine of n particles on `threads` threads; `cfg` gives the scheme (with the
/// lanes' size and epoch), the rest is set here.
template <int D, class Model>
DsmcPoint time_engine(std::size_t n, int threads, double min_collisions, std::uint64_t seed,
                      bool cpu_clock, dsmc::Config cfg = {}) {
  cfg.n = n;
  cfg.seed = seed;
  cfg.init = InitialState::delta;
  cfg.vhs_exponent = 0.5;
  dsmc::Engine<D, Model> e(cfg);
  e.set_threads(threads);
  e.run_until(0.5);
  e.reset_schedule_profile();
  const auto c0 = e.collisions(), k0 = e.candidates();
  const double t_run = 2.0 * min_collisions / static_cast<double>(n);
  const std::uint64_t tick0 = dsmc::ticks_now();
  const Stopwatch clock(cpu_clock && threads == 1);
  e.run_until(e.time() + t_run);
  const double w = clock.seconds();
  const double ticks = static_cast<double>(dsmc::ticks_now() - tick0);
  const double dc = static_cast<double>(e.collisions() - c0);
  const double dk = static_cast<double>(e.candidates() - k0);
  return {dc / w, dk / w, dc / dk, e.bytes_per_particle(), w, ticks / w, e.schedule_profile()};
}

/// The machine's ceiling for T threads: T independent one-thread engines (seeds differ)
/// started together, each on its own gas; returns their summed collision rate.
template <int D, class Model>
double concurrent_engines(std::size_t n, int T, double min_collisions, std::uint64_t seed,
                          const dsmc::Config& sc) {
  std::vector<double> rate(static_cast<std::size_t>(T));
  std::vector<std::thread> pool;
  for (int t = 1; t < T; ++t)
    pool.emplace_back([&, t] {
      rate[std::size_t(t)] = time_engine<D, Model>(n, 1, min_collisions,
                                                   seed + 1000u * std::uint64_t(t), false, sc)
                                 .collisions_per_s;
    });
  rate[0] = time_engine<D, Model>(n, 1, min_collisions, seed, false, sc).collisions_per_s;
  for (auto& th : pool) th.join();
  double total = 0.0;
  for (double r : rate) total += r;
  return total;
}

/// "schedule":[{"thread":0,"draw_set":..,...,"deferred":..},...]: each thread's ticks per
/// phase per candidate of the system (a thread's phases sum to the wall ticks per
/// candidate), and the fraction of its own candidates that it deferred.
std::string schedule_json(const std::vector<std::vector<dsmc::PhaseTicks>>& reps) {
  if (reps.empty() || reps.front().empty()) return "";
  std::vector<dsmc::PhaseTicks> sum(reps.front().size());
  for (const auto& r : reps)
    for (std::size_t t = 0; t < r.size() && t < sum.size(); ++t) sum[t].add(r[t]);
  double cand = 0.0;
  for (const auto& p : sum) cand += static_cast<double>(p.candidates);
  if (cand <= 0.0) return "";
  std::string j = ",\"schedule\":[";
  char buf[128];
  for (std::size_t t = 0; t < sum.size(); ++t) {
    std::snprintf(buf, sizeof buf, "%s{\"thread\":%zu", t ? "," : "", t);
    j += buf;
    for (int ph = 0; ph < dsmc::phase_count; ++ph) {
      std::snprintf(buf, sizeof buf, ",\"%s\":%.2f", dsmc::phase_names[std::size_t(ph)],
                    static_cast<double>(sum[t].ticks[std::size_t(ph)]) / cand);
      j += buf;
    }
    std::snprintf(buf, sizeof buf, ",\"deferred\":%.4f}",
                  static_cast<double>(sum[t].deferred) /
                      std::max(1.0, static_cast<double>(sum[t].candidates)));
    j += buf;
  }
  return j + "]";
}

/// One line per scheme and thread count. Within each repeat, the schemes take turns, and
/// within a scheme a one-thread engine, the runs of every thread count and the ceiling runs
/// alternate, so that drifts of a shared machine hit all of them alike.
template <int D, class Model>
void bench_point(std::ostream& out, const DsmcBenchOptions& o, std::size_t n) {
  const std::size_t nt = o.threads.size(), ns = o.schemes.size();
  std::vector<dsmc::Config> cases(ns);
  for (std::size_t s = 0; s < ns; ++s) {
    cases[s].scheme = registry::scheme(o.schemes[s]);
    cases[s].lane_size = o.lane_size;
    cases[s].epoch = o.epoch;
  }
  const auto at = [&](std::size_t s, std::size_t k) { return s * nt + k; };
  std::vector<std::vector<double>> rate(ns * nt), cand(ns * nt), acc(ns * nt), gain(ns * nt),
      tick_rate(ns * nt);
  std::vector<std::vector<std::vector<dsmc::PhaseTicks>>> schedule(ns * nt);
  std::vector<double> probe;
  double bytes = 0.0;
  for (int r = 0; r < o.reps; ++r) {
    const std::uint64_t seed = o.seed + std::uint64_t(r);
    for (std::size_t s = 0; s < ns; ++s) {
      double one = 0.0;  // the scheme's one-thread rate in this repeat
      for (std::size_t k = 0; k < nt; ++k) {
        const DsmcPoint p = time_engine<D, Model>(n, o.threads[k], o.min_collisions, seed,
                                                  o.cpu_clock, cases[s]);
        rate[at(s, k)].push_back(p.collisions_per_s);
        cand[at(s, k)].push_back(p.candidates_per_s);
        acc[at(s, k)].push_back(p.acceptance);
        tick_rate[at(s, k)].push_back(p.ticks_per_s);
        schedule[at(s, k)].push_back(p.schedule);
        bytes = p.bytes_per_particle;
        if (o.threads[k] == 1 && one == 0.0) one = p.collisions_per_s;
      }
      bool multi = false;
      for (int t : o.threads) multi |= t > 1;
      if (multi && one == 0.0)
        one = time_engine<D, Model>(n, 1, o.min_collisions, seed, false, cases[s])
                  .collisions_per_s;
      for (std::size_t k = 0; k < nt; ++k)
        gain[at(s, k)].push_back(
            o.threads[k] > 1
                ? concurrent_engines<D, Model>(n, o.threads[k], o.min_collisions, seed, cases[s]) /
                      one
                : 1.0);
    }
    probe.push_back(
        pair_update_probe<D>(n, std::max(2e6, o.min_collisions), seed, o.cpu_clock));
  }
  const double pr = median(probe);
  std::size_t exact = ns;
  for (std::size_t s = 0; s < ns; ++s)
    if (cases[s].scheme == dsmc::Scheme::exact) exact = s;
  for (std::size_t s = 0; s < ns; ++s) {
    const double base = median(rate[at(s, 0)]);
    for (std::size_t k = 0; k < nt; ++k) {
      const double cr = median(rate[at(s, k)]);
      const double ceiling = median(gain[at(s, k)]);
      const double speedup = cr / base * o.threads[0];
      char buf[1024];
      std::snprintf(buf, sizeof buf,
                    "{\"bench\":\"dsmc\",\"engine\":\"dsmc\",\"model\":\"%s\",\"dim\":%d,"
                    "\"n\":%zu,\"reps\":%d,\"scheme\":\"%s\",\"collisions_per_s\":%.4g,"
                    "\"candidates_per_s\":%.4g,"
                    "\"acceptance\":%.4f,\"bytes_per_particle\":%.1f,"
                    "\"probe_pair_updates_per_s\":%.4g,\"probe_ratio\":%.4f,\"threads\":%d,"
                    "\"speedup\":%.3f,\"efficiency\":%.3f,\"ceiling\":%.3f,\"of_ceiling\":%.3f,"
                    "\"ticks_per_s\":%.4g,\"clock\":\"%s\"",
                    std::string(Model::name).c_str(), D, n, o.reps, o.schemes[s].c_str(), cr,
                    median(cand[at(s, k)]), median(acc[at(s, k)]), bytes, pr, cr / pr,
                    o.threads[k], speedup, speedup / o.threads[k], ceiling, speedup / ceiling,
                    median(tick_rate[at(s, k)]),
                    o.cpu_clock && o.threads[k] == 1 ? "cpu" : "wall");
      out << buf;
      std::string extra;
      if (cases[s].scheme == dsmc::Scheme::lanes) {
        const dsmc::LaneShape shape =
            dsmc::lane_shape(cases[s], static_cast<std::uint32_t>(n), Particles<D>::stride);
        std::snprintf(buf, sizeof buf, ",\"lanes\":%u,\"lane_size\":%u,\"epoch\":%.17g",
                      shape.lanes, shape.lane_size, cases[s].epoch);
        extra += buf;
      }
      if (exact < ns) {
        std::snprintf(buf, sizeof buf, ",\"vs_exact\":%.3f", cr / median(rate[at(exact, k)]));
        extra += buf;
      }
      out << extra << schedule_json(schedule[at(s, k)]) << "}\n" << std::flush;
    }
  }
}

}  // namespace

void run_dsmc_bench(std::ostream& out, const DsmcBenchOptions& o) {
  registry::model(o.model);  // all options checked before any output
  for (int d : o.dims) registry::dimension(d);
  for (std::size_t n : o.ns)
    for (int d : o.dims) {
      registry::EngineChoice c;
      c.dim = d;
      c.model = o.model;
      registry::with_engine(c, [&](auto engine) {
        using Engine = typename decltype(engine)::type;
        if constexpr (registry::is_dsmc<Engine> && !registry::EngineTraits<Engine>::features.species)
          bench_point<Engine::dim, typename registry::EngineTraits<Engine>::Model>(out, o, n);
      });
    }
}

}  // namespace hypergas::studies
