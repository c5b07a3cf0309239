// sim/main.cpp -- the `hypergas` command: option structure, subcommands, exit codes.
//
// Exit codes: 0 success; 2 bad input (CLI11 parse errors and hypergas::InvalidInput, with
// one clear line on stderr); 1 any other failure; 130 interrupted (SIGINT/SIGTERM). On any
// non-zero exit the output folder holds nothing new (see output_dir.hpp).
#include <exception>
#include <filesystem>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "commands.hpp"
#include "hypergas/error.hpp"
#include "progress.hpp"

int main(int argc, char** argv) {
  using namespace hypergas::cli;
  CLI::App app{
      "hypergas: hard-sphere gases in D = 1..6 (velocity-space DSMC and event-driven MD).\n"
      "Without a subcommand: the default scene relaxes a non-equilibrium gas in every\n"
      "D = 1..6, prints a table and writes CSV and PNG files under --out.",
      "hypergas"};
  app.require_subcommand(0, 1);

  SceneOptions scene;
  app.add_option("--out,-o", scene.out, "default scene: output folder for CSV and PNG files")
      ->capture_default_str();
  app.add_option("--seed", scene.seed, "default scene: random seed")->capture_default_str();
  app.add_option("--n,-n", scene.n, "default scene: particles per dimension, >= 2")
      ->capture_default_str();
  app.add_option("--until", scene.until,
                 "default scene: end time in equilibrium mean collision times, > 0")
      ->capture_default_str();

  RunOptions run;
  CLI::App* run_app = app.add_subcommand("run", "run one simulation and write its files to --out");
  add_run_options(*run_app, run);

  BenchOptions bench;
  CLI::App* bench_app =
      app.add_subcommand("bench", "throughput: one JSON object per line on stdout");
  add_bench_options(*bench_app, bench);

  CLI::App* report_app = add_report_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "hypergas: {}\nRun with --help for the options.\n", e.what());
    return 2;
  }

  install_interrupt_handler();
  try {
    if (run_app->parsed()) {
      validate(run);
      return run_command(run);
    }
    if (bench_app->parsed()) {
      validate(bench);
      return bench_command(bench);
    }
    if (report_app->parsed()) return report_command();
    return default_scene(scene);
  } catch (const hypergas::InvalidInput& e) {
    fmt::print(stderr, "hypergas: {}\n", e.what());
    return 2;
  } catch (const Interrupted&) {
    fmt::print(stderr, "hypergas: interrupted; no output written\n");
    return 130;
  } catch (const std::exception& e) {
    fmt::print(stderr, "hypergas: error: {}\n", e.what());
    return 1;
  }
}
