// DSMC throughput (throughput.hpp): timed engine runs, the memory-bound probe, replicas.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "clock.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/dsmc/huge_pages.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/studies/replicas.hpp"
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

template <int D, class Model>
void bench_point(std::ostream& out, const DsmcBenchOptions& o, std::size_t n) {
  std::vector<double> rate, cand, acc, probe;
  double bytes = 0.0;
  for (int r = 0; r < o.reps; ++r) {
    const DsmcPoint p = time_engine<D, Model>(n, o.min_collisions, o.seed + r, o.cpu_clock);
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
                std::string(Model::name).c_str(), D, n, o.reps, cr, median(cand), median(acc),
                bytes, pr, cr / pr, o.cpu_clock ? "cpu" : "wall");
  out << buf << '\n' << std::flush;
  if (o.threads > 1) {  // aggregate throughput of independent replicas, one per thread
    using Replica = dsmc::HardSpheres;
    dsmc::Config cfg;
    cfg.n = n;
    cfg.seed = o.seed;
    cfg.init = InitialState::delta;
    std::vector<double> coll(o.threads), wall(o.threads);
    run_replicas<dsmc::Engine<D, Replica>>(cfg, o.threads, o.threads, [&](int r, auto& e) {
      const auto c0 = e.collisions();
      const Stopwatch clock(false);
      e.run_until(2.0 * o.min_collisions / static_cast<double>(n));
      coll[r] = static_cast<double>(e.collisions() - c0);
      wall[r] = clock.seconds();
    });
    double total = 0.0;
    for (int r = 0; r < o.threads; ++r) total += coll[r] / wall[r];
    std::snprintf(buf, sizeof buf,
                  "{\"bench\":\"dsmc_replicas\",\"engine\":\"dsmc\",\"model\":\"%s\",\"dim\":%d,"
                  "\"n\":%zu,\"threads\":%d,\"collisions_per_s\":%.4g}",
                  std::string(Replica::name).c_str(), D, n, o.threads, total);
    out << buf << '\n' << std::flush;
  }
}

}  // namespace

void run_dsmc_bench(std::ostream& out, const DsmcBenchOptions& o) {
  const auto model = registry::model(o.model);
  for (int d : o.dims) registry::dimension(d);  // all options checked before any output
  for (std::size_t n : o.ns)
    for (int d : o.dims)
      registry::dispatch(
          [&](auto dim, auto m) {
            bench_point<decltype(dim)::type::value, typename decltype(m)::type>(out, o, n);
          },
          registry::dimension(d), model);
}

}  // namespace hypergas::studies
