// sim/report_command.cpp -- `hypergas report`: error against run time (CSV + PNG).
//
// The study is the studies library's (hypergas/studies/report.hpp, shared with
// bench_report); this file gives it the command's options, exit codes and output-folder
// handling (all files or none). Under mpirun its replicas spread over the ranks
// (ranks.hpp: ReplicaRanks); rank 0 writes the files.
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "commands.hpp"
#include "hypergas/studies/replicas.hpp"
#include "hypergas/studies/report.hpp"
#include "output_dir.hpp"

namespace hypergas::cli {

namespace {
studies::ReportOptions report_options;
}

CLI::App* add_report_command(CLI::App& app) {
  CLI::App* r = app.add_subcommand(
      "report", "error against run time (work-precision study): CSV + PNG in --out");
  auto& o = report_options;
  r->add_option("--out,-o", o.out, "output folder (created if missing)")->capture_default_str();
  r->add_flag("--quick", o.quick, "about 15-30 s instead of about 80 s: fewer points and replicas");
  add_number(*r, "--seed", o.seed, "random seed");
  add_number(*r, "--threads,-j", o.threads, "replicas run on this many threads, 1..64");
  r->add_flag("--no-plot{false}", o.plot, "skip the PNG (gnuplot)");
  return r;
}

int report_command() {
  studies::ReportOptions o = report_options;
  if (o.threads < 1 || o.threads > 64)
    throw InvalidInput(fmt::format("--threads must be in 1..64, got {}", o.threads));
  if (!studies::replica_root()) {  // an MPI rank other than 0: its share of the replicas
    o.verbose = false;
    (void)studies::run_report_study(o);
    return 0;
  }
  OutputDir out(o.out);
  const studies::ReportResult res = studies::run_report_study(o);
  studies::write_report(res, out.staging(), o.plot);
  out.commit();
  fmt::print("{}", studies::report_summary(res));
  fmt::print("report written to {}/ in {:.1f} s\n", out.dir().string(), res.total_s);
  return 0;
}

}  // namespace hypergas::cli
