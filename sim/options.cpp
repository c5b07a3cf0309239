// sim/options.cpp -- option registration (with units and defaults in --help) and validation.
#include "options.hpp"

#include <cmath>
#include <fmt/core.h>
#include <fmt/ranges.h>

#include "hypergas/edmd/box.hpp"
#include "hypergas/error.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::cli {

namespace {
bool finite_positive(double x) { return std::isfinite(x) && x > 0.0; }

[[noreturn]] void bad(const std::string& msg) { throw InvalidInput(msg); }

void check_dim(int d, const char* opt) {
  if (d < min_dim || d > max_dim)
    bad(fmt::format("{} must be a dimension in {}..{}, got {}", opt, min_dim, max_dim, d));
}

void check_n(long long n) {
  if (n < 2) bad(fmt::format("--n must be at least 2 particles, got {}", n));
  if (n > (1LL << 31))
    bad(fmt::format("--n must be at most 2^31 = {} particles, got {}", 1LL << 31, n));
}

std::vector<double> jamming_list() {
  std::vector<double> v;
  for (int d = min_dim; d <= max_dim; ++d) v.push_back(jamming_packing(d));
  return v;
}

/// "dsmc delta, edmd maxwell": each engine's default initial state, for --help.
std::string default_inits() {
  std::string s;
  for (const auto& e : registry::engines)
    s += fmt::format("{}{} {}", s.empty() ? "" : ", ", e.name,
                     registry::name(registry::default_initial_state(e.value)));
  return s;
}

/// Checks `value` with the registry's lookup, which names the known values; the message
/// is prefixed with the option.
template <class Lookup>
void check_name(const char* option, const std::string& value, Lookup lookup) {
  try {
    lookup(value);
  } catch (const InvalidInput& e) {
    bad(fmt::format("{}: {}", option, e.what()));
  }
}

}  // namespace

double jamming_packing(int dim) {
  check_dim(dim, "dimension");
  return edmd::jamming_packing(dim);  // sources in include/hypergas/edmd/box.hpp
}

registry::EngineKind RunOptions::engine_kind() const { return registry::engine(engine); }

InitialState RunOptions::initial_state() const {
  return init.empty() ? registry::default_initial_state(engine_kind())
                      : registry::initial_state(init);
}

void add_run_options(CLI::App& app, RunOptions& o) {
  app.add_option("--engine", o.engine, registry::describe(registry::engines))
      ->capture_default_str();
  app.add_option("--dim,-d", o.dim, "dimension D, 1..6")->capture_default_str();
  app.add_option("--n,-n", o.n, "number of particles, >= 2")->capture_default_str();
  app.add_option("--out,-o", o.out,
                 "output folder (created if missing); files appear only when complete")
      ->required();
  app.add_flag("--json", o.json, "print the summary as one JSON object, the last stdout line");
  app.add_option("--model", o.model, "DSMC collision model: " + registry::describe_models())
      ->capture_default_str();
  app.add_option("--vhs-exponent", o.vhs_exponent,
                 "VHS rate exponent a: pair rate ~ |g|^a, in [0, 1] (hs is 1, maxwell 0)")
      ->capture_default_str();
  app.add_option("--init", o.init,
                 fmt::format("initial velocities: {} (default: {}; see "
                             "include/hypergas/initial_state.hpp)",
                             registry::describe(registry::initial_states), default_inits()));
  app.add_option("--until", o.until,
                 "end time; dsmc: equilibrium mean collision times (default 10); edmd: "
                 "sigma sqrt(m/kT) (default 20)");
  app.add_option("--every", o.every, "sampling interval, same unit as --until (default until/50)");
  app.add_option("--packing", o.packing,
                 fmt::format("edmd packing fraction eta (volume of the spheres / box volume), "
                             "below the D-dimensional jamming density ({} for D = 1..6)",
                             fmt::join(jamming_list(), ", ")))
      ->capture_default_str();
  app.add_option("--mass-ratio", o.mass_ratio,
                 "m2/m1 of a two-mass gas, finite and > 0 (1 = one species; use != 1 in D = 1)")
      ->capture_default_str();
  app.add_option("--fraction", o.fraction, "number fraction of species 2 (mass m2), in [0, 1]")
      ->capture_default_str();
  app.add_option("--temperature", o.temperature,
                 "initial kT in units of m1 v0^2 (dsmc; edmd fixes kT = 1), finite and > 0")
      ->capture_default_str();
  app.add_option("--seed", o.seed, "random seed (any 64-bit integer)")->capture_default_str();
  app.add_option("--threads,-j", o.threads,
                 "dsmc: run K independent replicas on K threads (files from replica 0, which "
                 "keeps --seed; summary adds totals and replica error bars); edmd: 1")
      ->capture_default_str();
}

void add_bench_options(CLI::App& app, BenchOptions& o) {
  app.add_option("--engine", o.engine,
                 fmt::format("{} | all", registry::join(registry::engine_names(), " | ")))
      ->capture_default_str();
  app.add_option("--dim,-d", o.dims, "dimensions to measure, each in 1..6 (repeatable)")
      ->capture_default_str();
  app.add_option("--n,-n", o.ns, "particle numbers to measure, each >= 2 (repeatable)")
      ->capture_default_str();
  app.add_option("--model", o.model,
                 "DSMC collision model: " + registry::join(registry::model_names(), " | "))
      ->capture_default_str();
  app.add_option("--packing", o.packing, "EDMD packing fraction eta")->capture_default_str();
  app.add_option("--reps", o.reps, "timed runs per point, the median is reported, 1..100")
      ->capture_default_str();
  app.add_option("--min-collisions", o.min_collisions,
                 "accepted collisions per timed run, >= 1000")
      ->capture_default_str();
  app.add_option("--threads,-j", o.threads,
                 "dsmc: > 1 adds a line with the aggregate rate of that many concurrent "
                 "independent replicas, 1..64")
      ->capture_default_str();
  app.add_option("--seed", o.seed, "random seed")->capture_default_str();
}

void validate(const RunOptions& o) {
  check_name("--engine", o.engine, registry::engine);
  check_dim(o.dim, "--dim");
  check_n(o.n);
  if (o.out.empty()) bad("--out must name an output folder");
  check_name("--model", o.model, registry::model);
  const registry::EngineKind e = o.engine_kind();
  const bool edmd = e == registry::EngineKind::edmd;
  if (edmd && o.model != dsmc::HardSpheres::name)
    bad(fmt::format("--model {} needs --engine {}: event-driven MD simulates hard spheres",
                    o.model, registry::name(registry::EngineKind::dsmc)));
  if (!(std::isfinite(o.vhs_exponent) && o.vhs_exponent >= 0.0 && o.vhs_exponent <= 1.0))
    bad(fmt::format("--vhs-exponent must be in [0, 1], got {}", o.vhs_exponent));
  if (!o.init.empty()) check_name("--init", o.init, registry::initial_state);
  if (o.until >= 0.0 || std::isnan(o.until))
    if (!finite_positive(o.until))
      bad(fmt::format("--until must be a finite time > 0, got {}", o.until));
  if (o.every >= 0.0 || std::isnan(o.every))
    if (!finite_positive(o.every))
      bad(fmt::format("--every must be a finite interval > 0, got {}", o.every));
  if (!finite_positive(o.packing))
    bad(fmt::format("--packing must be a finite fraction > 0, got {}", o.packing));
  const double jam = jamming_packing(o.dim);
  if (edmd && o.packing >= jam)
    bad(fmt::format("--packing {} is at or above the jamming density {} of hard spheres in "
                    "D = {}",
                    o.packing, jam, o.dim));
  if (!finite_positive(o.mass_ratio))
    bad(fmt::format("--mass-ratio must be a finite mass ratio > 0, got {}", o.mass_ratio));
  if (!(std::isfinite(o.fraction) && o.fraction >= 0.0 && o.fraction <= 1.0))
    bad(fmt::format("--fraction must be in [0, 1], got {}", o.fraction));
  if (!finite_positive(o.temperature))
    bad(fmt::format("--temperature must be a finite kT > 0, got {}", o.temperature));
  if (edmd && o.temperature != 1.0)
    bad("--temperature applies to --engine dsmc only (edmd units fix kT = 1)");
  if (o.threads < 1 || o.threads > 64)
    bad(fmt::format("--threads must be in 1..64, got {}", o.threads));
  if (edmd && o.threads != 1)
    bad("--threads applies to --engine dsmc only (the EDMD engine is sequential)");
}

void validate(const BenchOptions& o) {
  if (o.engine != "all") check_name("--engine (or all)", o.engine, registry::engine);
  if (o.dims.empty()) bad("--dim needs at least one dimension");
  for (int d : o.dims) check_dim(d, "--dim");
  if (o.ns.empty()) bad("--n needs at least one particle number");
  for (long long n : o.ns) check_n(n);
  check_name("--model", o.model, registry::model);
  if (!finite_positive(o.packing))
    bad(fmt::format("--packing must be a finite fraction > 0, got {}", o.packing));
  for (int d : o.dims)
    if (o.engine != registry::name(registry::EngineKind::dsmc) && o.packing >= jamming_packing(d))
      bad(fmt::format("--packing {} is at or above the jamming density {} in D = {}", o.packing,
                      jamming_packing(d), d));
  if (o.reps < 1 || o.reps > 100) bad(fmt::format("--reps must be in 1..100, got {}", o.reps));
  if (o.threads < 1 || o.threads > 64)
    bad(fmt::format("--threads must be in 1..64, got {}", o.threads));
  if (!(std::isfinite(o.min_collisions) && o.min_collisions >= 1000.0 &&
        o.min_collisions <= 1e12))
    bad(fmt::format("--min-collisions must be in [1000, 1e12], got {}", o.min_collisions));
}

}  // namespace hypergas::cli
