// sim/main.cpp -- the `hypergas` command: option structure, subcommands, exit codes.
//
// Compiled twice (sim/CMakeLists.txt): as `hypergas`, and with HYPERGAS_MEASURE_TOOL as
// `hypergas-measure`, which holds `bench` and `report` (the throughput and error-against-
// run-time measurements, hypergas_measures). `hypergas bench ...` and `hypergas report ...`
// execute hypergas-measure from the same folder with the same arguments, so the command's
// first build (scripts/setup.sh without arguments) compiles neither.
//
// Exit codes: 0 success; 2 bad input (CLI11 parse errors and hypergas::InvalidInput, with
// one clear line on stderr); 1 any other failure; 130 interrupted (SIGINT/SIGTERM). On any
// non-zero exit the output folder holds nothing new (see output_dir.hpp) except, after
// Ctrl-C of a `run`, its checkpoint.hgck, which `hypergas resume` continues.
#include <cerrno>
#include <cstring>
#include <exception>
#include <malloc.h>
#include <filesystem>
#include <optional>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "commands.hpp"
#include "hypergas/options/suggest.hpp"
#include "version.hpp"
#include "hypergas/studies/replicas.hpp"
#include "hypergas/error.hpp"
#include "progress.hpp"
#include "run_driver.hpp"

namespace {
/// CLI11's message, with its wording for a repeated option made plain.
std::string parse_message(const CLI::ParseError& e) {
  const std::string m = e.what();
  const std::string key = ": At Most 1 required but received ";
  const auto at = m.find(key);
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) && at != std::string::npos)
    return m.substr(0, at) + " was given more than once; give it once";
  return m;
}

/// One line for arguments the command does not know: the first unknown option (or word),
/// the (sub)command it was given to, and the nearest name it knows (options::nearest).
std::string extras_message(CLI::App& app) {
  CLI::App* where = &app;
  for (CLI::App* sub : app.get_subcommands())
    if (!sub->remaining().empty()) where = sub;
  const std::vector<std::string> extra = where->remaining();
  if (extra.empty()) return "hypergas: unexpected arguments (see --help)";
  std::string arg = extra.front();
  for (const std::string& a : extra)
    if (a.rfind('-', 0) == 0) {
      arg = a;
      break;
    }
  const bool option = arg.rfind('-', 0) == 0;
  std::vector<std::string> names;
  if (option) {
    for (const CLI::Option* opt : where->get_options())
      for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
  } else if (where == &app) {
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      names.push_back(sub->get_name());
  }
  // every message starts "hypergas:" (the contract, docs/design.md)
  const std::string who = where == &app ? "" : where->get_name() + ": ";
  return fmt::format("hypergas: {}unknown {} '{}'{}", who, option ? "option" : "argument", arg,
                     hypergas::options::did_you_mean(arg, names));
}
bool parsed(const CLI::App* sub) { return sub && sub->parsed(); }

#ifndef HYPERGAS_MEASURE_TOOL
/// Replaces this process by hypergas-measure from this program's folder with the same
/// arguments; returns only if that fails (exit code 2: not built, 1: not started).
int exec_measure_tool(int argc, char** argv) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path tool = self.parent_path() / "hypergas-measure";
  if (ec || !std::filesystem::exists(tool, ec)) {
    fmt::print(stderr, "hypergas: {} is done by hypergas-measure, which this build did not make "
                       "(bash scripts/setup.sh --all, or cmake --build build --target "
                       "hypergas_measure)\n", argv[1]);
    return 2;
  }
  std::vector<char*> args{const_cast<char*>(tool.c_str())};
  for (int i = 1; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  ::execv(tool.c_str(), args.data());
  fmt::print(stderr, "hypergas: cannot start {}: {}\n", tool.string(), std::strerror(errno));
  return 1;
}
#endif
}  // namespace

int main(int argc, char** argv) {
  using namespace hypergas::cli;
  // Blocks of 1 MiB and more come from mmap and go back to the system when freed. glibc's
  // default raises this threshold after the first such free (up to 32 MiB), after which the
  // snapshot buffers of a large run stay in the heap and the peak resident memory grows to
  // several times the live data (EDMD 3D, N = 256000: 948 against 410 B/particle).
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  CLI::App app{
      "hypergas: hard-sphere gases in D = 1..6 (velocity-space DSMC and event-driven MD).\n"
      "Without a subcommand: the default scene relaxes a non-equilibrium gas in every\n"
      "D = 1..6, prints a table and writes CSV and PNG files under --out.",
      "hypergas"};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", std::string(hypergas::cli::version_line()));

  CLI::App* run_app = nullptr;
  [[maybe_unused]] CLI::App* resume_app = nullptr;  // not in hypergas-measure
  CLI::App* sweep_app = nullptr;
  SceneOptions scene;
  RunArgs run;
  ResumeOptions resume;
  SweepOptions sweep;
  BenchOptions bench;
#ifdef HYPERGAS_MEASURE_TOOL
  CLI::App* bench_app =
      app.add_subcommand("bench", "throughput: one JSON object per line on stdout");
  add_bench_options(*bench_app, bench);
  CLI::App* report_app = add_report_command(app);
#else
  app.add_option("--out,-o", scene.out, "default scene: output folder for CSV and PNG files")
      ->capture_default_str();
  add_number(app, "--seed", scene.seed, "default scene: random seed");
  add_number(app, "--n,-n", scene.n, "default scene: particles per dimension, >= 2");
  add_number(app, "--until", scene.until,
             "default scene: end time in equilibrium mean collision times, > 0");

  run_app = app.add_subcommand("run", "run one simulation and write its files to --out");
  add_run_options(*run_app, run);

  // bench and report: every argument after them goes to hypergas-measure, --help included
  CLI::App* bench_app = app.add_subcommand(
      "bench", "throughput: one JSON object per line on stdout (bench --help: its options)");
  CLI::App* report_app = app.add_subcommand(
      "report", "error against run time (work-precision study): CSV + PNG in --out (report "
                "--help: its options)");
  for (CLI::App* tool : {bench_app, report_app}) {
    tool->prefix_command();
    tool->set_help_flag();
  }

  resume_app = add_resume_command(app, resume);
  sweep_app = add_sweep_command(app, sweep);
#endif

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help
    return app.exit(e);
  } catch (const CLI::ExtrasError&) {
    fmt::print(stderr, "{}\n", extras_message(app));
    return 2;
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "hypergas: {} (see --help)\n", parse_message(e));
    return 2;
  }

#ifndef HYPERGAS_MEASURE_TOOL
  if (bench_app->parsed() || report_app->parsed()) return exec_measure_tool(argc, argv);
#endif
  install_interrupt_handler();
  // Under mpirun/srun (and built with MPI): one MPI session for the commands that use ranks;
  // `run --replicas` and `report` hand their replicas out over the ranks.
  const bool ranked = parsed(run_app) || parsed(report_app) || parsed(sweep_app);
  if (ranked && !ranks::built_with_mpi() && ranks::launcher_size() > 1) {
    fmt::print(stderr, "hypergas: this build has no MPI (CMake found none when it was "
                       "configured), so its {} processes would each run the whole job; run it "
                       "without mpirun/srun, or install libopenmpi-dev and rebuild\n",
               ranks::launcher_size());
    return 2;
  }
  std::optional<ranks::Session> session;
  if (ranked) session.emplace();
  std::optional<ranks::ReplicaRanks> spread;
  if (session && session->size() > 1 && !parsed(sweep_app)) {
    spread.emplace(*session);
    hypergas::studies::set_replica_spread(&*spread);
  }
  // An error on one rank while others wait for it: end the job (MPI_Abort) with its code.
  const auto end = [&](int code) {
    if (session && session->size() > 1 && !parsed(sweep_app)) session->abort(code);
    return code;
  };
  try {
#ifdef HYPERGAS_MEASURE_TOOL
    if (bench_app->parsed()) {
      validate(bench);
      return bench_command(bench);
    }
    if (report_app->parsed()) return report_command();
    fmt::print(stderr, "hypergas-measure: give bench or report (it is run by hypergas bench "
                       "and hypergas report)\n");
    return 2;
#else
    if (parsed(run_app)) {
      const RunOptions o = run_options(run);
      if (session && session->size() > 1 && session->rank() == 0 && o.replicas == 1)
        fmt::print(stderr, "hypergas: note: under MPI, run spreads only --replicas over the "
                           "ranks; ranks 1..{} have nothing to do\n",
                   session->size() - 1);
      return run_command(o);
    }
    if (parsed(resume_app)) return resume_command(resume);
    if (parsed(sweep_app)) return sweep_command(sweep, *session);
    return default_scene(scene);
#endif
  } catch (const hypergas::InvalidInput& e) {
    fmt::print(stderr, "hypergas: {}\n", e.what());
    return end(2);
  } catch (const InterruptedWithCheckpoint& i) {
    fmt::print(stderr,
               "hypergas: interrupted at t = {:.6g}; checkpoint written to {}/{}\n"
               "Continue with: hypergas resume {}\n",
               i.time, i.dir.string(), Checkpointer::file_name, i.dir.string());
    return end(130);
  } catch (const Interrupted&) {
    fmt::print(stderr, "hypergas: interrupted; no output written\n");
    return end(130);
  } catch (const std::exception& e) {
    fmt::print(stderr, "hypergas: error: {}\n", e.what());
    return end(1);
  }
}
