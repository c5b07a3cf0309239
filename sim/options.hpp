// sim/options.hpp -- the command line of `hypergas run` and `hypergas bench`.
//
// The run options are the table's (hypergas/options/table.hpp): add_run_options registers
// each entry with CLI11, its help, unit and default derived from the entry, and collects the
// given text; run_options() turns it into validated values (the engine's defaults, then each
// given option through the table's checks). main() turns InvalidInput (and CLI11 parse
// errors) into stderr + exit code 2.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "hypergas/options/table.hpp"

// CLI11 is parsed only by the files that register options (it costs seconds per file).
namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace hypergas::cli {

using options::dsmc_config;
using options::edmd_config;
using options::jamming_packing;
using options::parse_duration;
using options::parse_number;
using options::RunOptions;
using options::two_species;
using options::validate;

/// The run options as given on a command line: each entry with its text, in parse order.
struct RunArgs {
  std::vector<std::pair<const options::Option*, std::string>> given;
};

/// Registers every option of the run table on `app`, collecting the given ones into `a`.
void add_run_options(CLI::App& app, RunArgs& a);
/// The validated options that `a` describes: defaults(engine), then each given option.
RunOptions run_options(const RunArgs& a);

/// Throughput study options of `hypergas bench` (the studies library's throughput study).
struct BenchOptions {
  std::string engine{registry::name(registry::EngineKind::dsmc)};  ///< an engine, or all
  std::vector<int> dims{1, 2, 3, 4, 5, 6};  ///< dimensions to measure
  std::vector<long long> ns{100000};        ///< particle numbers to measure
  std::string model{dsmc::HardSpheres::name};  ///< DSMC model
  double packing = 0.1;                     ///< EDMD packing fraction
  double start_packing = 0.0;               ///< EDMD lattice start packing (0: packing)
  int reps = 3;                             ///< timed runs per point (median reported)
  double min_collisions = 5e6;              ///< accepted collisions per timed run
  std::vector<int> threads{1};              ///< DSMC: thread counts to time (the run range)
  std::vector<std::string> schemes{"exact"};  ///< DSMC time schemes, timed in turn
  long long lane_size = 0;                  ///< DSMC lanes: particles per lane (0: default)
  double epoch = dsmc::Config{}.epoch;      ///< DSMC lanes: time between deals
  std::uint64_t seed = 1;
};

/// Registers the `bench` options on `app`, writing into `o`.
void add_bench_options(CLI::App& app, BenchOptions& o);
/// Checks every bench option; throws InvalidInput on the first bad one.
void validate(const BenchOptions& o);

/// Registers a numeric option that parses through parse_number (one value, or with a vector
/// target several); its default is shown in --help.
template <class T>
CLI::Option* add_number(CLI::App& app, const std::string& names, T& target,
                        const std::string& help);

}  // namespace hypergas::cli
