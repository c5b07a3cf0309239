// bench_edmd: EDMD collisions per second (one core) for the cases; JSON lines.
// Usage: bench_edmd [dim n packing [collisions [repeats [calendar|heap [auto|slab|horizon|filtered]]]]]
// (no arguments: the default cases; the last two pick the event queue and the neighbour
// scan, edmd/config.hpp).
#include <cstdlib>
#include <iostream>
#include <string>

#include "edmd_bench.hpp"

int main(int argc, char** argv) {
  using namespace hypergas::bench;
  const std::string queue = argc > 6 ? argv[6] : "calendar";
  const std::string scan = argc > 7 ? argv[7] : "auto";
  if (argc == 2 || argc == 3 || argc > 8 || (queue != "calendar" && queue != "heap") ||
      (scan != "auto" && scan != "slab" && scan != "horizon" && scan != "filtered")) {
    std::cerr << "Usage: bench_edmd [dim n packing [collisions [repeats [calendar|heap "
                 "[auto|slab|horizon|filtered]]]]]\n"
                 "EDMD collisions per CPU second, one JSON object per line; no arguments:\n"
                 "3D N = 4000, 32000, 256000 at eta = 0.26 and 6D N = 32000 at eta = 0.05.\n";
    const std::string a = argc > 1 ? argv[1] : "";
    return a == "-h" || a == "--help" ? 0 : 2;
  }
  try {
    if (argc >= 4) {
      EdmdCase c;
      c.dim = std::atoi(argv[1]);
      c.n = static_cast<std::size_t>(std::atoll(argv[2]));
      c.packing = std::atof(argv[3]);
      if (argc >= 5) c.collisions = static_cast<std::uint64_t>(std::atoll(argv[4]));
      if (argc >= 6) c.repeats = std::atoi(argv[5]);
      c.heap = queue == "heap";
      c.scan = scan == "slab"      ? hypergas::edmd::Scan::slab
               : scan == "horizon" ? hypergas::edmd::Scan::horizon
               : scan == "filtered" ? hypergas::edmd::Scan::filtered
                                   : hypergas::edmd::Scan::automatic;
      run_edmd_bench(c, std::cout);
      return 0;
    }
    for (const auto& c : default_edmd_cases()) run_edmd_bench(c, std::cout);
  } catch (const std::exception& e) {
    std::cerr << "bench_edmd: " << e.what() << '\n';
    return 2;
  }
}
