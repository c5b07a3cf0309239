// sim/bench_command.cpp -- `hypergas bench`: throughput, one JSON object per line on stdout.
//
// The measurements themselves live with the engines' benchmarks (bench/dsmc_bench.hpp and
// bench/edmd_bench.hpp) so that `bench_dsmc` and `hypergas bench` report the same numbers.
#include <iostream>

#include "commands.hpp"
#include "dsmc_bench.hpp"

namespace hypergas::cli {

int bench_command(const BenchOptions& o) {
  if (o.engine == "dsmc" || o.engine == "all") {
    bench::DsmcBenchOptions b;
    b.dims = o.dims;
    b.ns.assign(o.ns.begin(), o.ns.end());
    b.reps = o.reps;
    b.min_collisions = o.min_collisions;
    b.model = dsmc::parse_model(o.model);
    b.seed = o.seed;
    bench::run_dsmc_bench(std::cout, b);
  }
  if (o.engine == "edmd" || o.engine == "all")
    throw InvalidInput("hypergas bench: the edmd benchmark is not built into this version");
  return 0;
}

}  // namespace hypergas::cli
