// bench_dsmc: DSMC throughput, one JSON object per line (hypergas/studies/throughput.hpp).
// Usage: bench_dsmc [--dims 1,2,3] [--ns 10000,1000000] [--reps 3] [--min-collisions 5e6]
//                   [--model NAME] [--threads 1,2] [--clock wall|cpu]
// (NAME: a collision model of hypergas/registry.hpp)
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "hypergas/error.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/studies/throughput.hpp"

namespace {
template <class T>
std::vector<T> parse_list(const std::string& s) {
  std::vector<T> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(static_cast<T>(std::stod(item)));
  return out;
}
}  // namespace

int main(int argc, char** argv) {
  namespace registry = hypergas::registry;
  hypergas::studies::DsmcBenchOptions o;
  try {
    for (int i = 1; i < argc; i += 2) {
      const std::string k = argv[i];
      if (k == "-h" || k == "--help") {
        std::cout << "Usage: bench_dsmc [--dims 1,2,3] [--ns 10000,1000000] [--reps 3]\n"
                     "                  [--min-collisions 5e6] [--model "
                  << registry::join(registry::model_names(), "|")
                  << "] [--threads 1,2] [--clock wall|cpu]\n"
                     "DSMC throughput, one JSON object per line (same as hypergas bench).\n"
                     "--clock cpu: rates per CPU second of the thread (for A/B runs on a\n"
                     "shared machine; the default is wall seconds).\n";
        return 0;
      }
      if (i + 1 >= argc) throw hypergas::InvalidInput("option " + k + " needs a value");
      const std::string v = argv[i + 1];
      if (k == "--dims")
        o.dims = parse_list<int>(v);
      else if (k == "--ns")
        o.ns = parse_list<std::size_t>(v);
      else if (k == "--reps")
        o.reps = std::stoi(v);
      else if (k == "--min-collisions")
        o.min_collisions = std::stod(v);
      else if (k == "--threads")
        o.threads = parse_list<int>(v);
      else if (k == "--clock") {
        if (v != "wall" && v != "cpu") throw hypergas::InvalidInput("--clock must be wall or cpu");
        o.cpu_clock = v == "cpu";
      } else if (k == "--model") {
        registry::model(v);  // unknown names fail here, before any output
        o.model = v;
      } else
        throw hypergas::InvalidInput("unknown option " + k);
    }
    hypergas::studies::run_dsmc_bench(std::cout, o);
  } catch (const std::exception& e) {
    std::cerr << "bench_dsmc: " << e.what() << '\n';
    return 2;
  }
}
