// sim/bench_command.cpp -- `hypergas bench`: throughput, one JSON object per line on stdout.
//
// The measurements are the studies library's (hypergas/studies/throughput.hpp), so that
// `bench_dsmc`, `bench_edmd` and `hypergas bench` report the same numbers.
#include <iostream>

#include "commands.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/studies/throughput.hpp"

namespace hypergas::cli {

int bench_command(const BenchOptions& o) {
  // --engine names one engine of the registry, or "all".
  const auto runs = [&](registry::EngineKind e) {
    return o.engine == registry::name(e) || o.engine == "all";
  };
  if (runs(registry::EngineKind::dsmc)) {
    studies::DsmcBenchOptions b;
    b.dims = o.dims;
    b.ns.assign(o.ns.begin(), o.ns.end());
    b.reps = o.reps;
    b.min_collisions = o.min_collisions;
    b.model = o.model;
    b.threads.assign(o.threads.begin(), o.threads.end());
    b.schemes = o.schemes;
    b.lane_size = static_cast<std::uint32_t>(o.lane_size);
    b.epoch = o.epoch;
    b.seed = o.seed;
    studies::run_dsmc_bench(std::cout, b);
  }
  if (runs(registry::EngineKind::edmd)) {
    for (long long n : o.ns)
      for (int d : o.dims) {
        studies::EdmdCase c;
        c.dim = d;
        c.n = static_cast<std::size_t>(n);
        c.packing = o.packing;
        c.start_packing = o.start_packing;
        c.collisions = static_cast<std::uint64_t>(o.min_collisions);
        c.repeats = o.reps;
        c.seed = o.seed;
        studies::run_edmd_bench(c, std::cout);
      }
  }
  return 0;
}

}  // namespace hypergas::cli
