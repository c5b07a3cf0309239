// bench_edmd: EDMD collisions per second (one core), JSON lines
// (hypergas/studies/throughput.hpp).
// Usage: bench_edmd [dim n packing [collisions [repeats [SCAN]]]]
// No arguments: the default cases. SCAN picks the neighbour scan: auto (the engine's
// default for D and the packing) or a scan policy of edmd/scan.hpp.
#include <cstdlib>
#include <iostream>
#include <string>

#include "hypergas/registry.hpp"
#include "hypergas/studies/throughput.hpp"

int main(int argc, char** argv) {
  using namespace hypergas::studies;
  const std::string scans = hypergas::registry::join(edmd_scan_names(), "|");
  if (argc == 2 || argc == 3 || argc > 7) {
    std::cerr << "Usage: bench_edmd [dim n packing [collisions [repeats [" << scans
              << "]]]]\n"
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
      if (argc >= 7) c.scan = argv[6];
      run_edmd_bench(c, std::cout);
      return 0;
    }
    for (const auto& c : default_edmd_cases()) run_edmd_bench(c, std::cout);
  } catch (const std::exception& e) {
    std::cerr << "bench_edmd: " << e.what() << '\n';
    return 2;
  }
}
