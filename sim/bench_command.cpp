// sim/bench_command.cpp -- `hypergas bench`: throughput, one JSON object per line on stdout.
//
// The measurements themselves live with the engines' benchmarks (bench/dsmc_bench.hpp and
// bench/edmd_bench.hpp) so that `bench_dsmc`, `bench_edmd` and `hypergas bench` report the
// same numbers.
#include <algorithm>
#include <iostream>

#include "commands.hpp"
#include "dsmc_bench.hpp"
#include "edmd_bench.hpp"

namespace hypergas::cli {

int bench_command(const BenchOptions& o) {
  if (o.engine == "dsmc" || o.engine == "all") {
    bench::DsmcBenchOptions b;
    b.dims = o.dims;
    b.ns.assign(o.ns.begin(), o.ns.end());
    b.reps = o.reps;
    b.min_collisions = o.min_collisions;
    b.model = dsmc::parse_model(o.model);
    b.threads = o.threads;
    b.seed = o.seed;
    bench::run_dsmc_bench(std::cout, b);
  }
  if (o.engine == "edmd" || o.engine == "all") {
    for (long long n : o.ns)
      for (int d : o.dims) {
        bench::EdmdCase c;
        c.dim = d;
        c.n = static_cast<std::size_t>(n);
        c.packing = o.packing;
        c.collisions = static_cast<std::uint64_t>(o.min_collisions);
        c.repeats = o.reps;
        c.seed = o.seed;
        bench::run_edmd_bench(c, std::cout);
      }
  }
  return 0;
}

}  // namespace hypergas::cli
