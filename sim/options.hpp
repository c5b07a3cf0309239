// sim/options.hpp -- the options of `hypergas run` and `hypergas bench`, and their validation.
//
// Options are parsed by CLI11 into plain structs; `validate` then checks every value and
// throws hypergas::InvalidInput with a message naming the option, the value and what is
// allowed. main() turns InvalidInput (and CLI11 parse errors) into stderr + exit code 2.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/edmd/config.hpp"
#include "hypergas/registry.hpp"

namespace hypergas::cli {

/// Everything `hypergas run` takes. Engine, model and initial-state names are those of
/// hypergas/registry.hpp. Units: DSMC time in equilibrium mean collision times,
/// EDMD in sigma sqrt(m/kT) with sigma = m = kT = 1.
struct RunOptions {
  std::string engine{registry::name(registry::EngineKind::dsmc)};  ///< registry::engines
  int dim = 3;                   ///< D, 1..6
  long long n = 10000;           ///< particles (signed so that negative input is caught)
  std::string out;               ///< output folder (created; files written atomically)
  bool json = false;             ///< print summary.json's object as the last stdout line
  std::string model{dsmc::HardSpheres::name};  ///< DSMC collision model (registry::Models)
  double vhs_exponent = 0.5;     ///< VHS rate exponent a (rate ~ |g|^a), in [0, 1]
  std::string init;              ///< initial state name; empty = the engine's default
  double until = -1.0;           ///< end time; not given = engine default
  double every = -1.0;           ///< sampling interval; not given = until / 50
  double packing = 0.1;          ///< EDMD packing fraction eta
  double start_packing = 0.0;    ///< EDMD: lattice start packing, compressed to eta (0: eta)
  double mass_ratio = 1.0;       ///< m2 / m1 of a two-mass gas (1 = one species)
  double fraction = 0.5;         ///< number fraction of the heavy species
  double temperature = 1.0;      ///< initial kT (DSMC velocity scale; EDMD fixes kT = 1)
  std::uint64_t seed = 1;        ///< random seed
  int threads = 1;               ///< DSMC: threads of the one system (same result for any)
  int replicas = 1;              ///< DSMC: independent copies (seeds derived from --seed)
  double checkpoint_every = 0.0; ///< checkpoint every this much engine time (0 = off)
  std::string checkpoint_wall;   ///< checkpoint every this much wall time ("90s", "10min")
  std::vector<std::string> given;  ///< options given on the command line (long names)

  /// Whether option `name` (e.g. "--packing") was given on the command line.
  bool was_given(const std::string& name) const;
  /// --checkpoint-wall in seconds (0 if not given). Valid after validate().
  double checkpoint_wall_seconds() const;

  registry::EngineKind engine_kind() const;  ///< valid after validate()
  /// The initial state: --init, or the engine's default. Valid after validate().
  InitialState initial_state() const;
};

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
  std::vector<int> threads{1};              ///< DSMC: thread counts to time, each 1..64
  std::uint64_t seed = 1;
};

/// The engine configurations a run's (validated) options describe: the command and the
/// Python module build their engines from these.
dsmc::Config dsmc_config(const RunOptions& o);
edmd::Config edmd_config(const RunOptions& o);
/// Whether the run has two species (--mass-ratio != 1): the engines' Features::species.
bool two_species(const RunOptions& o);

/// Registers the `run` options on `app`, writing into `o`.
void add_run_options(CLI::App& app, RunOptions& o);
/// Registers the `bench` options on `app`, writing into `o`.
void add_bench_options(CLI::App& app, BenchOptions& o);

/// Checks every run option; throws InvalidInput with a clear message on the first bad one.
void validate(const RunOptions& o);
/// Fills o.given from the options `app` parsed (after app.parse()).
void record_given(const CLI::App& app, RunOptions& o);
/// Parses a wall-clock duration "<number>[s|min|h]" (no unit: seconds) to seconds; throws
/// InvalidInput unless it is finite and > 0.
double parse_duration(const std::string& option, const std::string& text);
/// Checks every bench option; throws InvalidInput on the first bad one.
void validate(const BenchOptions& o);

/// Parses the whole of `text` as a T for `option`, or throws CLI::ValidationError with a
/// message naming the option and the text: doubles in decimal or scientific notation (nan
/// and inf parse, and validate() refuses them with the option's range); signed integers also
/// as an exact integer in scientific notation (--n 1e6); unsigned integers (seeds) as plain
/// digits. Trailing characters (10x), hexadecimal and empty text are refused.
template <class T>
T parse_number(const std::string& option, const std::string& text);

/// Registers a numeric option that parses through parse_number (one value, or with a vector
/// target several); its default is shown in --help.
template <class T>
CLI::Option* add_number(CLI::App& app, const std::string& names, T& target,
                        const std::string& help);

/// Largest packing fraction (exclusive) an EDMD run may ask for in D dimensions: the
/// jamming density of edmd::jamming_packing (1, 0.82, 0.64, 0.46, 0.31, 0.20 for D = 1..6).
double jamming_packing(int dim);

}  // namespace hypergas::cli
