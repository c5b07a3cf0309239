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
  double until = -1.0;           ///< end time; < 0 = engine default
  double every = -1.0;           ///< sampling interval; < 0 = until / 50
  double packing = 0.1;          ///< EDMD packing fraction eta
  double mass_ratio = 1.0;       ///< m2 / m1 of a two-mass gas (1 = one species)
  double fraction = 0.5;         ///< number fraction of the heavy species
  double temperature = 1.0;      ///< initial kT (DSMC velocity scale; EDMD fixes kT = 1)
  std::uint64_t seed = 1;        ///< random seed
  int threads = 1;               ///< DSMC: independent replicas, one per thread

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
  int reps = 3;                             ///< timed runs per point (median reported)
  double min_collisions = 5e6;              ///< accepted collisions per timed run
  int threads = 1;                          ///< DSMC: > 1 also times that many replicas
  std::uint64_t seed = 1;
};

/// Registers the `run` options on `app`, writing into `o`.
void add_run_options(CLI::App& app, RunOptions& o);
/// Registers the `bench` options on `app`, writing into `o`.
void add_bench_options(CLI::App& app, BenchOptions& o);

/// Checks every run option; throws InvalidInput with a clear message on the first bad one.
void validate(const RunOptions& o);
/// Checks every bench option; throws InvalidInput on the first bad one.
void validate(const BenchOptions& o);

/// Largest packing fraction (exclusive) an EDMD run may ask for in D dimensions: the
/// jamming density of edmd::jamming_packing (1, 0.82, 0.64, 0.46, 0.31, 0.20 for D = 1..6).
double jamming_packing(int dim);

}  // namespace hypergas::cli
