// bench_edmd: EDMD collisions per second (one core) for the cases; JSON lines.
// Usage: bench_edmd [dim n packing collisions repeats]   (no arguments: the default cases)
#include <cstdlib>
#include <iostream>

#include "edmd_bench.hpp"

int main(int argc, char** argv) {
  using namespace hypergas::bench;
  if (argc >= 4) {
    EdmdCase c;
    c.dim = std::atoi(argv[1]);
    c.n = static_cast<std::size_t>(std::atoll(argv[2]));
    c.packing = std::atof(argv[3]);
    if (argc >= 5) c.collisions = static_cast<std::uint64_t>(std::atoll(argv[4]));
    if (argc >= 6) c.repeats = std::atoi(argv[5]);
    run_edmd_bench(c, std::cout);
    return 0;
  }
  for (const auto& c : default_edmd_cases()) run_edmd_bench(c, std::cout);
}
