// sim/options.cpp -- the run table on CLI11 (help, unit, default from each entry), and the
// bench options.
#include "options.hpp"

#include <cmath>
#include <type_traits>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <fmt/ranges.h>

#include "hypergas/error.hpp"
#include "hypergas/options/from_given.hpp"
#include "engine_runs.hpp"
#include "init_file.hpp"

namespace hypergas::cli {

namespace {
[[noreturn]] void bad(const std::string& msg) { throw InvalidInput(msg); }
bool finite_positive(double x) { return std::isfinite(x) && x > 0.0; }

/// parse_number inside a CLI11 callback: its InvalidInput as CLI11's parse error, which
/// main() reports with exit code 2.
template <class T>
T parse(const std::string& option, const std::string& text) {
  try {
    return parse_number<T>(option, text);
  } catch (const InvalidInput& e) {
    throw CLI::ValidationError(e.what());
  }
}
}  // namespace

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
          for (const std::string& s : v) target.push_back(parse<E>(name, s));
        },
        help);
    opt->default_str(fmt::format("{}", fmt::join(target, " ")));
  } else {
    opt = app.add_option_function<std::string>(
        names, [&target, name](const std::string& s) { target = parse<T>(name, s); },
        help);
    opt->default_str(fmt::format("{}", target));
  }
  using E = std::conditional_t<requires { typename T::value_type; }, T, std::vector<T>>;
  using V = typename E::value_type;
  opt->type_name(std::is_floating_point_v<V> ? "NUM" : std::is_signed_v<V> ? "INT" : "UINT");
  return opt;
}

template CLI::Option* add_number<double>(CLI::App&, const std::string&, double&,
                                         const std::string&);
template CLI::Option* add_number<int>(CLI::App&, const std::string&, int&, const std::string&);
template CLI::Option* add_number<long long>(CLI::App&, const std::string&, long long&,
                                            const std::string&);
template CLI::Option* add_number<std::uint64_t>(CLI::App&, const std::string&, std::uint64_t&,
                                                const std::string&);

void add_run_options(CLI::App& app, RunArgs& a) {
  std::string other_dsmc, other_edmd;
  for (const options::Option& opt : options::run_table()) {
    std::string names = options::cli_name(opt);
    if (opt.short_name) names += fmt::format(",-{}", opt.short_name);
    std::string help(opt.help);
    if (opt.details) help += " " + opt.details();
    if (!opt.unit.empty()) help += fmt::format(" [{}]", opt.unit);
    const std::string def = options::default_text(opt);
    const bool plain = opt.unset.empty() && def.find(" for ") == std::string::npos &&
                       opt.name != "engine";
    if (!plain && !def.empty()) help += fmt::format(" (default {})", def);
    if (opt.engines != options::Engines::both)
      help = fmt::format("{} only: {}", opt.engines == options::Engines::dsmc ? "dsmc" : "edmd",
                         help);
    const options::Option* p = &opt;
    CLI::Option* o = nullptr;
    if (options::type_name(opt) == "FLAG") {
      o = app.add_flag_callback(names, [&a, p] { a.given.emplace_back(p, "true"); }, help);
    } else {
      o = app.add_option_function<std::string>(
          names, [&a, p](const std::string& s) { a.given.emplace_back(p, s); }, help);
      o->type_name(std::string(options::type_name(opt)));
      if (plain && !def.empty()) o->default_str(def);
    }
    if (opt.required_cli) o->required();
    if (opt.engines == options::Engines::dsmc) other_dsmc += " " + options::cli_name(opt);
    if (opt.engines == options::Engines::edmd) other_edmd += " " + options::cli_name(opt);
  }
  app.footer(fmt::format("Options of the other engine are refused: edmd only:{}; dsmc only:{}.",
                         other_edmd, other_dsmc));
}

RunOptions run_options(const RunArgs& a) {
  RunOptions o = options::from_given(a.given, apply_init_file);
  options::validate_span(o, sampling_start(o));
  return o;
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
             "dsmc: thread counts to time one system with, each as `run --threads` allows "
             "(repeatable or comma-separated: -j 1,2); each line adds speedup and efficiency "
             "against the first, the ceiling (T one-thread engines run at once: their summed "
             "rate over one alone) and each thread's phase ticks per candidate")
      ->delimiter(',');
  app.add_option("--scheme", o.schemes,
                 "dsmc: time schemes to time, in turn within each repeat (repeatable or "
                 "comma-separated: --scheme exact,lanes): " +
                     registry::join(registry::scheme_names(), " | ") +
                     "; a line per scheme and thread count, with vs_exact (its rate over the "
                     "exact scheme's at that thread count) when exact is timed too")
      ->delimiter(',')
      ->capture_default_str();
  add_number(app, "--lane-size", o.lane_size, "dsmc lanes: particles per lane (0: the default)");
  add_number(app, "--epoch", o.epoch, "dsmc lanes: time between deals (mean collision times)");
  add_number(app, "--seed", o.seed, "random seed");
}

void validate(const BenchOptions& o) {
  const auto check_name = [](const char* option, const std::string& v, auto lookup) {
    try {
      lookup(v);
    } catch (const InvalidInput& e) {
      bad(fmt::format("{}: {}", option, e.what()));
    }
  };
  if (o.engine != "all")
    check_name("--engine (or all)", o.engine, [](const std::string& v) { registry::engine(v); });
  if (o.dims.empty()) bad("--dim needs at least one dimension");
  for (int d : o.dims) options::check_dim(d, "--dim");
  if (o.ns.empty()) bad("--n needs at least one particle number");
  for (long long n : o.ns) options::check_n(n, "--n");
  check_name("--model", o.model, [](const std::string& v) { registry::model(v); });
  if (!finite_positive(o.packing))
    bad(fmt::format("--packing must be a finite fraction > 0, got {}", o.packing));
  const bool edmd = o.engine != registry::name(registry::EngineKind::dsmc);
  for (int d : o.dims)
    if (edmd && o.packing >= jamming_packing(d))
      bad(fmt::format("--packing {} is at or above the jamming density {} in D = {}", o.packing,
                      jamming_packing(d), d));
  if (o.start_packing != 0.0) options::check_start_packing(o.start_packing, o.packing);
  if (edmd && o.packing > 0.99)
    for (int d : o.dims)
      if (d == 1) bad(fmt::format("--packing {} in D = 1: at most 0.99", o.packing));
  if (o.reps < 1 || o.reps > 100) bad(fmt::format("--reps must be in 1..100, got {}", o.reps));
  if (o.schemes.empty()) bad("--scheme needs at least one scheme");
  for (const std::string& s : o.schemes)
    check_name("--scheme", s, [](const std::string& v) { registry::scheme(v); });
  if (o.lane_size < 0 || o.lane_size == 1 || o.lane_size > 2147483648LL)
    bad(fmt::format("--lane-size must be 0 (the default) or in 2..2^31, got {}", o.lane_size));
  if (!finite_positive(o.epoch))
    bad(fmt::format("--epoch must be a finite time > 0, got {}", o.epoch));
  if (o.threads.empty()) bad("--threads needs at least one thread count");
  for (int t : o.threads) options::check_threads(t, "--threads");
  if (!(std::isfinite(o.min_collisions) && o.min_collisions >= 1000.0 &&
        o.min_collisions <= 1e12))
    bad(fmt::format("--min-collisions must be in [1000, 1e12], got {}", o.min_collisions));
}

}  // namespace hypergas::cli
