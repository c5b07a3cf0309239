// sim/options.cpp -- option registration (with units and defaults in --help) and validation.
#include "options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <type_traits>
#include <fmt/core.h>
#include <unistd.h>
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

/// The lattice start of an LS compression lies in (0, packing].
void check_start_packing(double start, double packing) {
  if (!(std::isfinite(start) && start > 0.0 && start <= packing))
    bad(fmt::format("--start-packing must be > 0 and at most --packing {}, got {}", packing,
                    start));
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

namespace {
/// Refuses a particle number whose state would not fit in this machine's memory.
void check_memory(long long n, int dim, bool edmd) {
  // Bytes per particle, a lower estimate: DSMC the padded velocities and a species byte;
  // EDMD the [position, clock, velocity] record plus ~150 B of events, cells and calendar.
  const double per = edmd ? 8.0 * hypergas::detail::record_stride(dim) + 150.0
                          : 8.0 * hypergas::detail::padded_stride(dim) + 1.0;
  const double need = per * static_cast<double>(n);
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return;
  const double have = static_cast<double>(pages) * static_cast<double>(page);
  if (need > have)
    bad(fmt::format("--n {} needs about {:.3g} GB of memory for the {} state; this machine has "
                    "{:.3g} GB",
                    n, need / 1e9, edmd ? "edmd" : "dsmc", have / 1e9));
}
}  // namespace

template <class T>
T parse_number(const std::string& option, const std::string& text) {
  const char* b = text.data();
  const char* e = b + text.size();
  const auto fail = [&](const char* what) -> T {
    throw CLI::ValidationError(fmt::format("{} must be {}, got '{}'", option, what, text));
  };
  if constexpr (std::is_floating_point_v<T>) {
    T x{};
    const auto r = std::from_chars(b, e, x);
    if (r.ec == std::errc::result_out_of_range) return fail("a number within double range");
    if (text.empty() || r.ec != std::errc{} || r.ptr != e) return fail("a number");
    return x;
  } else {
    T x{};
    const auto r = std::from_chars(b, e, x);
    if (!text.empty() && r.ec == std::errc{} && r.ptr == e) return x;
    const char* what = std::is_signed_v<T> ? "an integer" : "an integer >= 0 (decimal digits)";
    if constexpr (std::is_signed_v<T>) {  // 1e6, 2.5e3: exact integers in scientific form
      double d = 0.0;
      const auto rd = std::from_chars(b, e, d);
      if (!text.empty() && rd.ec == std::errc{} && rd.ptr == e && std::isfinite(d) &&
          d == std::floor(d) && std::fabs(d) < 9.0e18)
        if (d >= static_cast<double>(std::numeric_limits<T>::min()) &&
            d <= static_cast<double>(std::numeric_limits<T>::max()))
          return static_cast<T>(d);
    }
    if (r.ec == std::errc::result_out_of_range)
      return fail(std::is_signed_v<T> ? "an integer of a sensible size" : "below 2^64");
    return fail(what);
  }
}

template <class T>
CLI::Option* add_number(CLI::App& app, const std::string& names, T& target,
                        const std::string& help) {
  const std::string name = "--" + names.substr(2, names.find(',') - 2);
  CLI::Option* opt = nullptr;
  if constexpr (requires { typename T::value_type; }) {
    using E = typename T::value_type;
    opt = app.add_option_function<std::vector<std::string>>(
        names,
        [&target, name](const std::vector<std::string>& v) {
          target.clear();
          for (const std::string& s : v) target.push_back(parse_number<E>(name, s));
        },
        help);
    opt->default_str(fmt::format("{}", fmt::join(target, " ")));
  } else {
    opt = app.add_option_function<std::string>(
        names, [&target, name](const std::string& s) { target = parse_number<T>(name, s); },
        help);
    opt->default_str(fmt::format("{}", target));
  }
  using E = std::conditional_t<requires { typename T::value_type; }, T, std::vector<T>>;
  using V = typename E::value_type;
  opt->type_name(std::is_floating_point_v<V> ? "NUM" : std::is_signed_v<V> ? "INT" : "UINT");
  return opt;
}

template double parse_number<double>(const std::string&, const std::string&);
template int parse_number<int>(const std::string&, const std::string&);
template long long parse_number<long long>(const std::string&, const std::string&);
template std::uint64_t parse_number<std::uint64_t>(const std::string&, const std::string&);
template CLI::Option* add_number<double>(CLI::App&, const std::string&, double&,
                                         const std::string&);
template CLI::Option* add_number<int>(CLI::App&, const std::string&, int&, const std::string&);
template CLI::Option* add_number<long long>(CLI::App&, const std::string&, long long&,
                                            const std::string&);
template CLI::Option* add_number<std::uint64_t>(CLI::App&, const std::string&, std::uint64_t&,
                                                const std::string&);

double jamming_packing(int dim) {
  check_dim(dim, "dimension");
  return edmd::jamming_packing(dim);  // sources in include/hypergas/edmd/box.hpp
}

bool RunOptions::was_given(const std::string& name) const {
  return std::find(given.begin(), given.end(), name) != given.end();
}

double RunOptions::checkpoint_wall_seconds() const {
  return checkpoint_wall.empty() ? 0.0 : parse_duration("--checkpoint-wall", checkpoint_wall);
}

void record_given(const CLI::App& app, RunOptions& o) {
  o.given.clear();
  for (const CLI::Option* opt : app.get_options())
    if (opt->count() > 0 && !opt->get_lnames().empty())
      o.given.push_back("--" + opt->get_lnames().front());
}

double parse_duration(const std::string& option, const std::string& text) {
  std::size_t pos = 0;
  double x = 0.0;
  try {
    x = std::stod(text, &pos);
  } catch (const std::exception&) {
    bad(fmt::format("{} must be a duration such as 90s, 10min or 2h, got '{}'", option, text));
  }
  const std::string unit = text.substr(pos);
  double f = 0.0;
  if (unit.empty() || unit == "s") f = 1.0;
  else if (unit == "min" || unit == "m") f = 60.0;
  else if (unit == "h") f = 3600.0;
  else bad(fmt::format("{}: unknown unit '{}' in '{}' (use s, min or h)", option, unit, text));
  if (!(std::isfinite(x) && x > 0.0 && x * f <= 1e9))
    bad(fmt::format("{} must be a duration > 0 and at most 1e9 s, got '{}'", option, text));
  return x * f;
}

registry::EngineKind RunOptions::engine_kind() const { return registry::engine(engine); }

InitialState RunOptions::initial_state() const {
  return init.empty() ? registry::default_initial_state(engine_kind())
                      : registry::initial_state(init);
}

void add_run_options(CLI::App& app, RunOptions& o) {
  app.add_option("--engine", o.engine, registry::describe(registry::engines))
      ->capture_default_str();
  add_number(app, "--dim,-d", o.dim, "dimension D, 1..6");
  add_number(app, "--n,-n", o.n, "number of particles, >= 2 (1e6 is read as 1000000)");
  app.add_option("--out,-o", o.out,
                 "output folder (created if missing); files appear only when complete")
      ->required();
  app.add_flag("--json", o.json, "print the summary as one JSON object, the last stdout line");
  app.add_option("--model", o.model, "DSMC collision model: " + registry::describe_models())
      ->capture_default_str();
  add_number(app, "--vhs-exponent", o.vhs_exponent,
                 "VHS rate exponent a: pair rate ~ |g|^a, in [0, 1] (hs is 1, maxwell 0)");
  app.add_option("--init", o.init,
                 fmt::format("initial velocities: {} (default: {}; see "
                             "include/hypergas/initial_state.hpp)",
                             registry::describe(registry::initial_states), default_inits()));
  add_number(app, "--until", o.until,
                 "end time; dsmc: equilibrium mean collision times (default 10); edmd: "
                 "sigma sqrt(m/kT) (default 20)")
      ->default_str("");
  add_number(app, "--every", o.every, "sampling interval, same unit as --until (default until/50)")
      ->default_str("");
  add_number(app, "--packing", o.packing,
                 fmt::format("edmd packing fraction eta (volume of the spheres / box volume), "
                             "below the D-dimensional jamming density ({} for D = 1..6)",
                             fmt::join(jamming_list(), ", ")));
  add_number(app, "--start-packing", o.start_packing,
                 "edmd: start from the lattice at this packing, below --packing, and compress "
                 "(Lubachevsky-Stillinger) to --packing: a dense fluid or glass instead of a "
                 "crystal (default: start at --packing)")
      ->default_str("");
  add_number(app, "--mass-ratio", o.mass_ratio,
                 "m2/m1 of a two-mass gas, finite and > 0 (1 = one species; use != 1 in D = 1)")
      ->capture_default_str();
  add_number(app, "--fraction", o.fraction, "number fraction of species 2 (mass m2), in [0, 1]");
  add_number(app, "--temperature", o.temperature,
                 "initial kT in units of m1 v0^2 (dsmc; edmd fixes kT = 1), finite and > 0")
      ->capture_default_str();
  add_number(app, "--seed", o.seed, "random seed, an integer in 0..2^64-1");
  add_number(app, "--threads,-j", o.threads,
                 "dsmc: run the one system on T threads, 1..64; every file is bit for bit "
                 "the same for every T")
      ->capture_default_str();
  add_number(app, "--replicas", o.replicas,
                 "dsmc: run K independent copies, 1..64 (files from copy 0, which keeps "
                 "--seed; summary adds totals and replica error bars)")
      ->capture_default_str();
  add_number(app, "--checkpoint-every", o.checkpoint_every,
                 "write OUT/checkpoint.hgck at the first sampling time after every T time "
                 "units (same unit as --until); continue a stopped run with `hypergas resume "
                 "OUT`. Ctrl-C always writes one and stops")
      ->default_str("");
  app.add_option("--checkpoint-wall", o.checkpoint_wall,
                 "also write a checkpoint after this much wall time, e.g. 90s, 10min, 2h");
  app.footer(
      "Options of the other engine are refused: --packing is edmd only; --model, "
      "--vhs-exponent (with --model vhs), --temperature, --threads and --replicas are dsmc "
      "only.");
}

void add_bench_options(CLI::App& app, BenchOptions& o) {
  app.add_option("--engine", o.engine,
                 fmt::format("{} | all", registry::join(registry::engine_names(), " | ")))
      ->capture_default_str();
  add_number(app, "--dim,-d", o.dims, "dimensions to measure, each in 1..6 (repeatable)");
  add_number(app, "--n,-n", o.ns, "particle numbers to measure, each >= 2 (repeatable)");
  app.add_option("--model", o.model,
                 "DSMC collision model: " + registry::join(registry::model_names(), " | "))
      ->capture_default_str();
  add_number(app, "--packing", o.packing, "EDMD packing fraction eta");
  add_number(app, "--start-packing", o.start_packing,
                 "EDMD: compress from the lattice at this packing to --packing (default: none)")
      ->default_str("");
  add_number(app, "--reps", o.reps, "timed runs per point, the median is reported, 1..100");
  add_number(app, "--min-collisions", o.min_collisions,
                 "accepted collisions per timed run, >= 1000");
  add_number(app, "--threads,-j", o.threads,
                 "dsmc: thread counts to time one system with, each 1..64 (repeatable or "
                 "comma-separated: -j 1,2); each line adds speedup and efficiency against the "
                 "first")
      ->delimiter(',');
  add_number(app, "--seed", o.seed, "random seed");
}

void validate(const RunOptions& o) {
  check_name("--engine", o.engine, registry::engine);
  check_dim(o.dim, "--dim");
  check_n(o.n);
  if (o.out.empty()) bad("--out must name an output folder");
  check_name("--model", o.model, registry::model);
  const registry::EngineKind e = o.engine_kind();
  const bool edmd = e == registry::EngineKind::edmd;
  if (!(std::isfinite(o.vhs_exponent) && o.vhs_exponent >= 0.0 && o.vhs_exponent <= 1.0))
    bad(fmt::format("--vhs-exponent must be in [0, 1], got {}", o.vhs_exponent));
  if (!o.init.empty()) check_name("--init", o.init, registry::initial_state);
  const char* other = edmd ? "dsmc" : "edmd";
  for (const char* opt : edmd ? std::vector<const char*>{"--model", "--vhs-exponent",
                                                         "--temperature", "--threads",
                                                         "--replicas"}
                              : std::vector<const char*>{"--packing", "--start-packing"})
    if (o.was_given(opt))
      bad(fmt::format("{} applies to --engine {} only, not to --engine {}", opt, other,
                      o.engine));
  if (o.was_given("--vhs-exponent") && o.model != dsmc::VariableHardSpheres::name)
    bad(fmt::format("--vhs-exponent applies to --model {} only, not to --model {}",
                    dsmc::VariableHardSpheres::name, o.model));
  if (o.was_given("--until") && !finite_positive(o.until))
    bad(fmt::format("--until must be a finite time > 0, got {}", o.until));
  if (o.was_given("--every") && !finite_positive(o.every))
    bad(fmt::format("--every must be a finite interval > 0, got {}", o.every));
  const double until = o.was_given("--until") ? o.until : (edmd ? 20.0 : 10.0);
  if (until > 1e12) bad(fmt::format("--until must be at most 1e12, got {}", until));
  if (o.was_given("--every") && until / o.every > 1e6)
    bad(fmt::format("--until / --every = {:.3g} samples; at most 1e6 (each is a row of "
                    "moments.csv)",
                    until / o.every));
  if (o.was_given("--checkpoint-every") && !finite_positive(o.checkpoint_every))
    bad(fmt::format("--checkpoint-every must be a finite time > 0, got {}", o.checkpoint_every));
  if (!o.checkpoint_wall.empty()) (void)parse_duration("--checkpoint-wall", o.checkpoint_wall);
  if ((o.checkpoint_every > 0.0 || !o.checkpoint_wall.empty()) && o.replicas != 1)
    bad("--checkpoint-every and --checkpoint-wall need --replicas 1 (one system)");
  if (!finite_positive(o.packing))
    bad(fmt::format("--packing must be a finite fraction > 0, got {}", o.packing));
  const double jam = jamming_packing(o.dim);
  if (edmd && o.packing >= jam)
    bad(fmt::format("--packing {} is at or above the jamming density {} of hard spheres in "
                    "D = {}",
                    o.packing, jam, o.dim));
  if (o.was_given("--start-packing")) check_start_packing(o.start_packing, o.packing);
  // 1D: the collision rate grows as 1 / (1 - eta) (measured: 835, 8493, 84933 collisions of
  // N = 30 in t = 0.5 at eta = 0.99, 0.999, 0.9999), so a run near 1 never ends.
  if (edmd && o.dim == 1 && o.packing > 0.99)
    bad(fmt::format("--packing {} in D = 1: at most 0.99 (the collision rate grows as "
                    "1 / (1 - packing))",
                    o.packing));
  if (!finite_positive(o.mass_ratio))
    bad(fmt::format("--mass-ratio must be a finite mass ratio > 0, got {}", o.mass_ratio));
  if (!(std::isfinite(o.fraction) && o.fraction >= 0.0 && o.fraction <= 1.0))
    bad(fmt::format("--fraction must be in [0, 1], got {}", o.fraction));
  if (!finite_positive(o.temperature))
    bad(fmt::format("--temperature must be a finite kT > 0, got {}", o.temperature));
  // Speeds ~ sqrt(kT); kinetic-energy sums of 1e9 particles must stay far from overflow.
  if (!(o.temperature >= 1e-100 && o.temperature <= 1e100))
    bad(fmt::format("--temperature must be in [1e-100, 1e100], got {}", o.temperature));
  if (o.threads < 1 || o.threads > 64)
    bad(fmt::format("--threads must be in 1..64, got {}", o.threads));
  if (o.replicas < 1 || o.replicas > 64)
    bad(fmt::format("--replicas must be in 1..64, got {}", o.replicas));
  check_memory(o.n, o.dim, edmd);
}

namespace {
/// What both engine configurations take from the options alike.
template <class Config>
Config common_config(const RunOptions& o) {
  Config cfg;
  cfg.n = static_cast<std::size_t>(o.n);
  cfg.seed = o.seed;
  cfg.init = o.initial_state();
  cfg.initial.fraction = o.fraction;
  cfg.initial.mass_ratio = o.mass_ratio;
  return cfg;
}
}  // namespace

dsmc::Config dsmc_config(const RunOptions& o) {
  auto cfg = common_config<dsmc::Config>(o);
  cfg.vhs_exponent = o.vhs_exponent;
  cfg.initial.kT = o.temperature;
  return cfg;
}

edmd::Config edmd_config(const RunOptions& o) {
  auto cfg = common_config<edmd::Config>(o);
  cfg.packing = o.packing;
  cfg.start_packing = o.start_packing;
  cfg.initial.kT = 1.0;  // EDMD units: kT = 1
  return cfg;
}

bool two_species(const RunOptions& o) { return o.mass_ratio != 1.0; }

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
  if (o.start_packing != 0.0) check_start_packing(o.start_packing, o.packing);
  if (o.engine != registry::name(registry::EngineKind::dsmc) && o.packing > 0.99)
    for (int d : o.dims)
      if (d == 1) bad(fmt::format("--packing {} in D = 1: at most 0.99", o.packing));
  if (o.reps < 1 || o.reps > 100) bad(fmt::format("--reps must be in 1..100, got {}", o.reps));
  if (o.threads.empty()) bad("--threads needs at least one thread count");
  for (int t : o.threads)
    if (t < 1 || t > 64) bad(fmt::format("--threads must be in 1..64, got {}", t));
  if (!(std::isfinite(o.min_collisions) && o.min_collisions >= 1000.0 &&
        o.min_collisions <= 1e12))
    bad(fmt::format("--min-collisions must be in [1000, 1e12], got {}", o.min_collisions));
}

}  // namespace hypergas::cli
