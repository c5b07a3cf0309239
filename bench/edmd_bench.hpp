// bench/edmd_bench.hpp -- EDMD throughput benchmark, reusable by `hypergas bench --engine
// edmd`. Prints one JSON object per line:
//   {"bench":"edmd","dim":3,"n":32000,"packing":0.26,"repeat":0,"collisions":...,
//    "wall_s":...,"collisions_per_s":...,"bytes_per_particle":...,"Z":...}
// and, after the repeats of a case, a line with "stat":"median".
// Setup (lattice, compression, equilibration of `warmup` collisions per particle) is not
// timed; the timed part is `collisions` collision events on one core. collisions_per_s is
// per CPU second of the running thread (wall_s is also printed; on a shared machine it is
// larger).
#pragma once

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <vector>

#include "bench_clock.hpp"
#include "hypergas/edmd/engine.hpp"

namespace hypergas::bench {

/// One benchmark case: dimension, N, packing fraction, timed collisions, repeats.
struct EdmdCase {
  int dim = 3;
  std::size_t n = 32000;
  double packing = 0.26;
  std::uint64_t collisions = 2000000;
  int repeats = 3;
  double warmup = 2.0;  ///< collisions per particle before timing
  std::uint64_t seed = 1;
  bool heap = false;  ///< time the binary-heap event queue instead of the calendar queue
  edmd::Scan scan = edmd::Scan::automatic;  ///< neighbour-cell choice (edmd/config.hpp)
};

namespace detail {
template <int D, class Queue>
void edmd_case(const EdmdCase& c, std::ostream& out) {
  const char* queue = c.heap ? "heap" : "calendar";
  std::vector<double> rates;
  for (int r = 0; r < c.repeats; ++r) {
    edmd::Config cfg;
    cfg.n = c.n;
    cfg.packing = c.packing;
    cfg.seed = c.seed + static_cast<std::uint64_t>(r);
    cfg.scan = c.scan;
    edmd::Engine<D, Features{.positions = true}, Queue> e(cfg);
    const auto warm = static_cast<std::uint64_t>(c.warmup * static_cast<double>(c.n) / 2.0);
    while (e.collisions() < warm) e.step();
    e.reset_observables();
    const std::uint64_t c0 = e.collisions(), x0 = e.crossings(), s0 = e.stale_events(),
                        p0 = e.pairs_tested(), n0 = e.scans();
    const Stopwatch wall_clock(false), cpu_clock(true);
    while (e.collisions() - c0 < c.collisions) e.step();
    const double wall = wall_clock.seconds();
    const double cpu = cpu_clock.seconds();
    const double rate = static_cast<double>(c.collisions) / cpu;
    rates.push_back(rate);
    char buf[640];
    std::snprintf(buf, sizeof buf,
                  "{\"bench\":\"edmd\",\"queue\":\"%s\",\"scan\":\"%s\",\"dim\":%d,\"n\":%zu,"
                  "\"packing\":%.6g,\"repeat\":%d,"
                  "\"collisions\":%llu,\"wall_s\":%.4f,\"cpu_s\":%.4f,\"collisions_per_s\":%.1f,"
                  "\"bytes_per_particle\":%.1f,\"cells_per_side\":%d,\"Z\":%.5f,"
                  "\"crossings_per_collision\":%.3f,\"stale_per_collision\":%.3f,"
                  "\"pairs_per_collision\":%.1f,\"scans_per_collision\":%.3f}",
                  queue, e.path_filter() ? "filtered" : e.horizon_scan() ? "horizon" : "slab", D, c.n, c.packing, r,
                  static_cast<unsigned long long>(c.collisions), wall, cpu,
                  rate, e.bytes_per_particle(), e.cells_per_side(), e.pressure_Z(),
                  static_cast<double>(e.crossings() - x0) / static_cast<double>(c.collisions),
                  static_cast<double>(e.stale_events() - s0) / static_cast<double>(c.collisions),
                  static_cast<double>(e.pairs_tested() - p0) / static_cast<double>(c.collisions),
                  static_cast<double>(e.scans() - n0) / static_cast<double>(c.collisions));
    out << buf << std::endl;
  }
  std::sort(rates.begin(), rates.end());
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "{\"bench\":\"edmd\",\"stat\":\"median\",\"queue\":\"%s\",\"dim\":%d,"
                "\"n\":%zu,\"packing\":%.6g,\"repeats\":%d,\"collisions_per_s\":%.1f}",
                queue, D, c.n, c.packing, c.repeats,
                rates[rates.size() / 2]);
  out << buf << std::endl;
}
}  // namespace detail

/// Runs one case (dimension 1..6 dispatched here) and prints its JSON lines to `out`.
inline void run_edmd_bench(const EdmdCase& c, std::ostream& out) {
  if (c.dim < 1 || c.dim > 6) throw InvalidInput("bench: dimension must be 1..6");
  for_each_dim([&](auto tag) {
    constexpr int D = decltype(tag)::value;
    if (D != c.dim) return;
    if (c.heap)
      detail::edmd_case<D, edmd::EventQueue>(c, out);
    else
      detail::edmd_case<D, edmd::CalendarQueue>(c, out);
  });
}

/// The cases: 3D at eta = 0.26 for N = 4000, 32000, 256000 (DynamO anchors 125-145k,
/// 115-126k, 51-68k collisions/s) and 6D at N = 32000, eta = 0.05 (6D jams at 0.20; at
/// eta = 0.1 the D_6 lattice of 32000 sites is too tight and the Lubachevsky-Stillinger
/// compression that fixes it takes minutes at the present 6D rate), 2e5 timed collisions.
inline std::vector<EdmdCase> default_edmd_cases() {
  return {{3, 4000, 0.26}, {3, 32000, 0.26}, {3, 256000, 0.26}, {6, 32000, 0.05, 200000}};
}

}  // namespace hypergas::bench
