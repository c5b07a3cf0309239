// bench_report -- the error-against-run-time study (hypergas/studies/report.hpp) as a
// standalone program; `hypergas report` runs the same code.
//   bench_report [--quick] [--out DIR] [--seed S] [--threads K] [--no-plot]
// Writes DIR/work_precision.csv, slopes.csv, finite_n.csv, ntc.csv, work_precision.png.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "hypergas/error.hpp"
#include "hypergas/studies/report.hpp"

int main(int argc, char** argv) {
  hypergas::studies::ReportOptions o;
  try {
    for (int k = 1; k < argc; ++k) {
      const std::string a = argv[k];
      auto next = [&]() -> std::string {
        if (k + 1 >= argc) throw hypergas::InvalidInput(a + " needs a value");
        return argv[++k];
      };
      if (a == "--quick") o.quick = true;
      else if (a == "--no-plot") o.plot = false;
      else if (a == "--out") o.out = next();
      else if (a == "--seed") o.seed = std::stoull(next());
      else if (a == "--threads") o.threads = std::stoi(next());
      else throw hypergas::InvalidInput("unknown option " + a);
    }
    return hypergas::studies::run_report(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_report: %s\n", e.what());
    return 2;
  }
}
