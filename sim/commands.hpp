// sim/commands.hpp -- the subcommands of `hypergas`, each in its own file.
#pragma once

#include <cstdint>
#include <string>

#include "hypergas/checkpoint.hpp"
#include "options.hpp"
#include "ranks.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace hypergas::cli {

/// Options of the default scene (`hypergas` with no subcommand).
struct SceneOptions {
  std::string out = "results";  ///< folder for the CSV and PNG files
  std::uint64_t seed = 2026;    ///< random seed
  long long n = 20000;          ///< particles per dimension
  double until = 12.0;          ///< end time in equilibrium mean collision times (1D: 3x)
};

/// `hypergas`: relaxes a non-equilibrium gas in every D = 1..6, prints one table row per
/// D, writes CSV and PNG plots. Returns the exit code.
int default_scene(const SceneOptions& o);
/// `hypergas run`: one simulation, files into --out (checkpoints there too). With `resume`,
/// continues the checkpoint it reads (positioned after its header). `quiet`: nothing on
/// stdout and no progress bar (the cases of a sweep). Returns the exit code.
int run_command(const RunOptions& o, checkpoint::Reader* resume = nullptr, bool quiet = false);

/// Options of `hypergas resume`.
struct ResumeOptions {
  std::string dir;     ///< the output folder of the stopped run
  bool json = false;   ///< print the summary as JSON, as `run --json`
  double until = 0.0;  ///< continue to this time instead of the run's own (0: its own)
};
/// Registers `hypergas resume` on `app`, writing into `o`; returns the subcommand.
CLI::App* add_resume_command(CLI::App& app, ResumeOptions& o);
/// `hypergas resume DIR`: continues the run whose checkpoint DIR holds. Returns the exit code.
int resume_command(const ResumeOptions& o);
/// `hypergas bench`: throughput, one JSON object per line on stdout. Returns the exit code.
int bench_command(const BenchOptions& o);

/// Options of `hypergas sweep` (sweep_command.cpp).
struct SweepOptions {
  std::string plan;    ///< PLAN.toml (may be empty with --resume)
  std::string out;     ///< the sweep folder DIR
  std::string resume;  ///< DIR of a sweep to continue
  bool json = false;   ///< print the sweep's figures as one JSON object, the last stdout line
};
/// Registers `hypergas sweep` on `app`, writing into `o`; returns the subcommand.
CLI::App* add_sweep_command(CLI::App& app, SweepOptions& o);
/// `hypergas sweep`: the cases of a plan, over the ranks of `session` (one process without
/// MPI). Returns the exit code (on every rank).
int sweep_command(const SweepOptions& o, const ranks::Session& session);

/// Registers `hypergas report` and its options on `app` (error against run time, the study
/// of hypergas/studies/report.hpp); returns the subcommand.
CLI::App* add_report_command(CLI::App& app);
/// Runs `hypergas report` (after parsing). Returns the exit code.
int report_command();

}  // namespace hypergas::cli
