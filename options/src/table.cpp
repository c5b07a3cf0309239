// options/src/table.cpp -- the run options (the one table), their defaults, and setting and
// printing a value by its entry.
#include "hypergas/options/table.hpp"

#include <array>
#include <cmath>
#include <fmt/core.h>
#include <fmt/ranges.h>

#include "hypergas/error.hpp"
#include "reject.hpp"

namespace hypergas::options {

using detail::reject;

namespace {

using E = Engines;
using U = Use;
using R = RunOptions;

constexpr std::string_view time_unit =
    "dsmc: equilibrium mean collision times; edmd: sigma sqrt(m/kT)";
constexpr std::string_view mean_free_time_unit =
    "dsmc: equilibrium mean collision times; edmd: mean free times measured in the "
    "equilibration";

void check_model(std::string_view v) { (void)registry::model(v); }
std::string schemes_help() { return registry::describe(registry::schemes); }
void check_duration(std::string_view v) { (void)parse_duration("--checkpoint-wall", std::string(v)); }
std::string engines_help() { return registry::describe(registry::engines); }
std::string models_help() { return registry::describe_models(); }
std::string inits_help() {
  return registry::describe(registry::initial_states) +
         " (see include/hypergas/initial_state.hpp)";
}
std::string jamming_help() {
  std::vector<double> v;
  for (int d = min_dim; d <= max_dim; ++d) v.push_back(jamming_packing(d));
  return fmt::format("below the D-dimensional jamming density ({} for D = 1..6)",
                     fmt::join(v, ", "));
}

/// The named choices of Field: parse(name) throws InvalidInput naming the known names.
template <class T>
struct Named : std::false_type {};
template <>
struct Named<registry::EngineKind> : std::true_type {
  static registry::EngineKind parse(std::string_view v) { return registry::engine(v); }
  static std::string_view name(registry::EngineKind e) { return registry::name(e); }
};
template <>
struct Named<dsmc::Scheme> : std::true_type {
  static dsmc::Scheme parse(std::string_view v) { return registry::scheme(v); }
  static std::string_view name(dsmc::Scheme s) { return registry::name(s); }
};
template <>
struct Named<InitialState> : std::true_type {
  static InitialState parse(std::string_view v) { return registry::initial_state(v); }
  static std::string_view name(InitialState s) { return registry::name(s); }
};
template <>
struct Named<dsmc::Drive> : std::true_type {
  static dsmc::Drive parse(std::string_view v) { return drive_kind(v); }
  static std::string_view name(dsmc::Drive d) { return drive_name(d); }
};
template <>
struct Named<dsmc::Thermostat> : std::true_type {
  static dsmc::Thermostat parse(std::string_view v) { return thermostat_kind(v); }
  static std::string_view name(dsmc::Thermostat t) { return thermostat_name(t); }
};

constexpr double pos_open = 0.0;  // lower end of "> 0" ranges (open)

// clang-format off
const Option table[] = {
  {"engine", 0, E::both, U::command, &R::engine, {}, nullptr, engines_help, "", "the engine:", "", false, false},
  {"dim", 'd', E::both, U::engine, &R::dim, {1, 6, false, false, "a dimension in 1..6"}, nullptr, nullptr, "", "dimension D, 1..6", "", false, false},
  {"n", 'n', E::both, U::engine, &R::n, {2, 2147483648.0, false, false, "a number of particles in 2..2^31"}, nullptr, nullptr, "", "number of particles, >= 2 (1e6 is read as 1000000)", "", false, false},
  {"out", 'o', E::both, U::command, &R::out, {}, nullptr, nullptr, "", "output folder (created if missing); files appear only when complete, replace an earlier run's, and a folder with other files is refused", "", false, true},
  {"json", 0, E::both, U::command, &R::json, {}, nullptr, nullptr, "", "print the summary as one JSON object, the last stdout line", "", false, false},
  {"model", 0, E::dsmc, U::engine, &R::model, {}, check_model, models_help, "", "collision model:", "", false, false},
  {"vhs-exponent", 0, E::dsmc, U::engine, &R::vhs_exponent, {0, 1, false, false, "in [0, 1]"}, nullptr, nullptr, "", "VHS rate exponent a: pair rate ~ |g|^a, in [0, 1] (hs is 1, maxwell 0; with --model vhs only)", "", false, false},
  {"init", 0, E::both, U::engine, &R::init, {}, nullptr, inits_help, "", "initial velocities:", "", true, false},
  {"until", 0, E::both, U::span, &R::until, {pos_open, 1e12, true, false, "a finite time > 0 and at most 1e12"}, nullptr, nullptr, time_unit, "end time (with --every: at most 1e6 sampling intervals)", "", false, false},
  {"every", 0, E::both, U::span, &R::every, {pos_open, 1e308, true, false, "a finite interval > 0"}, nullptr, nullptr, time_unit, "sampling interval, rounded so that it divides the sampled span: the rows are evenly spaced and the last is at --until (include/hypergas/schedule.hpp); one longer than the span gives rows at the start and --until only (said on stderr)", "until/50", false, false},
  {"equilibration", 0, E::edmd, U::command, &R::equilibration, {pos_open, 1e12, true, false, "a finite time > 0, below --until"}, nullptr, nullptr, time_unit, "time the start equilibrates before sampling begins: the measurement window (Z, collision rate, the outputs) is [T, --until]", "until/5", false, false},
  {"histogram-every", 0, E::both, U::command, &R::histogram_every, {pos_open, 1e308, true, false, "a finite interval > 0"}, nullptr, nullptr, time_unit, "also write speed_histograms.csv (and speed_histograms.png): the speed histogram at every m-th sampling instant from the first, m = round(T / sampling interval), at least 1", "off", false, false},
  {"trajectory-every", 0, E::both, U::command, &R::trajectory_every, {pos_open, 1e308, true, false, "a finite interval > 0"}, nullptr, nullptr, time_unit, "also write trajectory.h5 (H5MD 1.1, docs/h5md.md: velocities; EDMD also positions, images and the box; observables): a frame at every m-th sampling instant from the first, m = round(T / sampling interval), at least 1; h5py and MDAnalysis read it; not with EDMD --shear-rate (a periodic H5MD box has no Lees-Edwards offset)", "off", false, false},
  {"init-file", 0, E::both, U::command, &R::init_file, {}, nullptr, nullptr, "", "start from the state in this H5MD file (a trajectory.h5, or any H5MD file with velocities; EDMD also positions in a cubic periodic box): it sets --dim and --n (EDMD: --packing too), and from the masses the species (mass 1: species 0; one other mass: species 1, --mass-ratio and --fraction); the run starts at t = 0 with its own seed", "", false, false},
  {"init-frame", 0, E::both, U::command, &R::init_frame, {-1e15, 1e15, false, false, "an integer frame index, |K| <= 1e15"}, nullptr, nullptr, "", "with --init-file: the frame to start from, 0 the first, negative from the end (-1 the last)", "-1 (the last)", false, false},
  {"restitution", 0, E::both, U::engine, &R::restitution, {0, 1, false, false, "in [0, 1]"}, nullptr, nullptr, "", "coefficient of normal restitution alpha: each collision's impulse along the normal is scaled by (1 + alpha)/2 and the gas cools (granular gas; 1 = elastic). dsmc: the freely cooling gas is kept in scaled velocities, time runs in mean collision times at the current temperature, and moments.csv gives T and real_time (docs/validation.md)", "", false, false},
  {"scheme", 0, E::dsmc, U::engine, &R::scheme, {}, nullptr, schemes_help, "", "time scheme. exact: the reference, and as fast as any below about 1e6 particles; lanes: from about 1e6 particles or for more than one thread (1.7-2.5x exact on one core at 1e6-1e7 in 3D, 1/M bias in the dynamics, exact equilibrium; docs/validation.md, \"The lanes scheme\"); ntc: Bird's scheme, for comparison:", "", false, false},
  {"dt", 0, E::dsmc, U::engine, &R::dt, {pos_open, 1e308, true, false, "a finite step > 0"}, nullptr, nullptr, "mean collision times", "with --scheme ntc: the time step, at most the sampling interval (each step ends at a sampling instant)", "", false, false},
  {"lane-size", 0, E::dsmc, U::engine, &R::lane_size, {0, 2147483648.0, false, false, "0 or a number of particles in 2..2^31"}, nullptr, nullptr, "particles", "with --scheme lanes: particles per lane M; the gas is cut into L = round(N / M) lanes", "2^19 bytes of velocities: 16384 in 3D, 8192 in 5D and 6D", false, false},
  {"epoch", 0, E::dsmc, U::engine, &R::epoch, {pos_open, 1e308, true, false, "a finite time > 0"}, nullptr, nullptr, "mean collision times", "with --scheme lanes: time between two deals of the particles into lanes", "", false, false},
  {"drive", 0, E::dsmc, U::engine, &R::drive, {}, nullptr, nullptr, "", "energy input of a granular gas: none (the homogeneous cooling state) or white-noise (random kicks that hold the first-Sonine temperature at --temperature; hard spheres, --restitution < 1)", "", false, false},
  {"drive-dt", 0, E::dsmc, U::engine, &R::drive_dt, {pos_open, 1, true, false, "a finite interval > 0 and at most 1"}, nullptr, nullptr, "mean collision times", "with --drive white-noise: interval between the kicks", "", false, false},
  {"shear-rate", 0, E::both, U::engine, &R::shear_rate, {0, 100, false, false, "a finite rate in [0, 100]"}, nullptr, nullptr, "per mean collision time at the initial T", "uniform shear flow u_x = a y (D >= 2), writes pressure_tensor.csv and the rheology summary keys (docs/validation.md, \"Uniform shear flow\"); dsmc (--scheme exact): in the frame moving with the flow, dV_x/dt = -a V_y between collisions, exactly; edmd: Lees-Edwards sliding boundaries from t = 0, a per ideal-gas mean collision time (D 2^D eta sqrt(kT/pi) per unit time), the exact kinetic + collisional pressure tensor. 0: no flow", "", false, false},
  {"thermostat", 0, E::both, U::engine, &R::thermostat, {}, nullptr, nullptr, "", "with --shear-rate: none (viscous heating; dsmc keeps the gas in scaled velocities with real_time, as for cooling) or isokinetic (holds T; elastic gases; dsmc: the Gaussian -zeta V exactly; edmd: the peculiar velocities rescaled every 0.1 mean collision times)", "", false, false},
  {"tc-time", 0, E::edmd, U::engine, &R::tc_time, {0, 1e308, false, false, "a finite time >= 0"}, nullptr, nullptr, "sigma sqrt(m/kT)", "with --restitution < 1: a collision within this time of either particle's previous one is elastic (the TC model of Luding and McNamara against inelastic collapse)", "", false, false},
  {"packing", 0, E::edmd, U::engine, &R::packing, {pos_open, 1, true, false, "a finite fraction > 0 and at most 1"}, nullptr, jamming_help, "", "packing fraction eta (volume of the spheres / box volume),", "", false, false},
  {"start-packing", 0, E::edmd, U::engine, &R::start_packing, {pos_open, 1, true, true, "> 0 and < 1"}, nullptr, nullptr, "", "start from the lattice at this packing, at most --packing, and compress (Lubachevsky-Stillinger) to --packing: a dense fluid or glass instead of a crystal", "start at --packing", false, false},
  {"mass-ratio", 0, E::both, U::engine, &R::mass_ratio, {pos_open, 1e308, true, false, "a finite mass ratio > 0"}, nullptr, nullptr, "", "m2/m1 of a two-mass gas (1 = one species; use != 1 in D = 1)", "", false, false},
  {"fraction", 0, E::both, U::engine, &R::fraction, {0, 1, false, false, "in [0, 1]"}, nullptr, nullptr, "", "number fraction of species 2 (mass m2), with --mass-ratio other than 1; round(fraction N) must leave both species at least one particle", "", true, false},
  {"temperature", 0, E::dsmc, U::engine, &R::temperature, {1e-100, 1e100, false, false, "a finite kT > 0 in [1e-100, 1e100]"}, nullptr, nullptr, "m1 v0^2", "initial kT (edmd fixes kT = 1)", "", true, false},
  {"seed", 0, E::both, U::engine, &R::seed, {0, 1.8446744073709552e19, false, false, "an integer in 0..2^64-1"}, nullptr, nullptr, "", "random seed", "", false, false},
  {"threads", 'j', E::dsmc, U::engine, &R::threads, {1, 256, false, false, "in 1..256"}, nullptr, nullptr, "", "run the one system on T threads; every file is bit for bit the same for every T. --scheme lanes shares its lanes out among the T threads; the exact and ntc schemes run on one thread whatever T is (their block schedule measured slower than one thread: docs/benchmarks.md)", "", false, false},
  {"replicas", 0, E::dsmc, U::command, &R::replicas, {1, 64, false, false, "in 1..64"}, nullptr, nullptr, "", "run K independent copies (files from copy 0, which keeps --seed; summary adds totals and replica error bars)", "", false, false},
  {"checkpoint-every", 0, E::both, U::command, &R::checkpoint_every, {pos_open, 1e308, true, false, "a finite time > 0"}, nullptr, nullptr, time_unit, "write OUT/checkpoint.hgck at the first sampling time after every T time units; continue a stopped run with `hypergas resume OUT`. Ctrl-C always writes one and stops", "off", false, false},
  {"checkpoint-wall", 0, E::both, U::command, &R::checkpoint_wall, {}, check_duration, nullptr, "", "also write a checkpoint after this much wall time, e.g. 90s, 10min, 2h", "off", false, false},
  {"transport", 0, E::both, U::command, &R::transport, {}, nullptr, nullptr, "", "also measure viscosity, thermal conductivity and self-diffusion from equilibrium fluctuations (transport.csv, correlations.csv, transport.png); dsmc: Green-Kubo after t = 20 (with --scheme lanes viscosity and conductivity only: its deals move particles between slots, so no particle can be followed); edmd: Einstein-Helfand and Green-Kubo with kinetic and collisional parts, after the equilibration, against Enskog; one species, D >= 2, no checkpoints (Ctrl-C stops it without output); run long: errors fall as 1/sqrt(until), and the values carry O(1/N) terms (docs/validation.md)", "", false, false},
  {"correlation-dt", 0, E::both, U::command, &R::correlation_dt, {pos_open, 1, true, false, "a finite interval > 0 and at most 1"}, nullptr, nullptr, mean_free_time_unit, "with --transport: sampling interval of the fluxes (dsmc: rounded to divide the --every interval)", "", false, false},
  {"correlation-time", 0, E::both, U::command, &R::correlation_time, {pos_open, 1e4, true, false, "a finite time > 0 and at most 1e4"}, nullptr, nullptr, mean_free_time_unit, "with --transport: longest lag of the correlation functions", "", false, false},
  {"tagged", 0, E::both, U::command, &R::tagged, {1, 4096, false, false, "in 1..4096"}, nullptr, nullptr, "", "with --transport: tagged particles whose velocity autocorrelation gives self-diffusion (default 32 for dsmc, where --scheme exact only; 256 for edmd)", "", false, false},
  {"structure", 0, E::edmd, U::command, &R::structure, {}, nullptr, nullptr, "", "also measure the radial distribution function g(r) with its contact value and the structure factor S(k) at the snapshots after the equilibration (rdf.csv, structure_factor.csv, structure.png)", "", false, false},
  {"rdf-max", 0, E::edmd, U::command, &R::rdf_max, {1.1, 1e4, false, false, "a finite length in [1.1, 1e4]"}, nullptr, nullptr, "sigma", "with --structure: largest r of g(r) (at most half the box side)", "", false, false},
  {"k-max", 0, E::edmd, U::command, &R::k_max, {pos_open, 1e3, true, false, "a finite wave number > 0 and at most 1e3"}, nullptr, nullptr, "1/sigma", "with --structure: largest |k| of S(k)", "", false, false},
};
// clang-format on

void check_range(const Option& opt, double v, const std::string& shown) {
  const Range& r = opt.range;
  const bool ok = std::isfinite(v) && (r.lo_open ? v > r.lo : v >= r.lo) &&
                  (r.hi_open ? v < r.hi : v <= r.hi);
  if (!ok) reject(fmt::format("--{} must be {}, got {}", opt.name, r.must, shown));
}

void given(RunOptions& o, const Option& opt) {
  const std::string n = cli_name(opt);
  if (!o.was_given(n)) o.given.push_back(n);
}

[[noreturn]] void wrong_type(const Option& opt, const char* what) {
  throw std::logic_error(fmt::format("option --{} is not {}", opt.name, what));
}

}  // namespace

std::span<const Option> run_table() { return table; }

const Option* find(std::string_view name) {
  for (const Option& o : table) {
    if (o.name == name) return &o;
    if (python_name(o) == name) return &o;
  }
  return nullptr;
}

bool applies(const Option& opt, registry::EngineKind e) {
  const unsigned bit = e == registry::EngineKind::dsmc ? 1u : 2u;
  return (static_cast<unsigned>(opt.engines) & bit) != 0;
}

std::string cli_name(const Option& opt) { return "--" + std::string(opt.name); }

std::string python_name(const Option& opt) {
  std::string s(opt.name);
  for (char& c : s)
    if (c == '-') c = '_';
  return s;
}

std::string_view type_name(const Option& opt) {
  return std::visit(
      [](auto m) -> std::string_view {
        using T = std::remove_reference_t<decltype(std::declval<R&>().*m)>;
        if constexpr (std::is_same_v<T, double>) return "NUM";
        else if constexpr (std::is_same_v<T, std::uint64_t>) return "UINT";
        else if constexpr (std::is_same_v<T, bool>) return "FLAG";
        else if constexpr (std::is_same_v<T, std::string> || Named<T>::value) return "TEXT";
        else return "INT";
      },
      opt.field);
}

RunOptions defaults(registry::EngineKind e) {
  const dsmc::Config d;
  const edmd::Config m;
  const bool dsmc = e == registry::EngineKind::dsmc;
  RunOptions o;
  o.engine = e;
  o.dim = 3;
  // Engine parameters: the engine's own Config defaults (the other engine's options keep
  // theirs, for --help).
  o.n = static_cast<long long>(dsmc ? d.n : m.n);
  o.seed = dsmc ? d.seed : m.seed;
  o.init = dsmc ? d.init : m.init;
  o.mass_ratio = dsmc ? d.initial.mass_ratio : m.initial.mass_ratio;
  o.fraction = dsmc ? d.initial.fraction : m.initial.fraction;
  o.temperature = d.initial.kT;
  o.model = std::string(dsmc::HardSpheres::name);
  o.vhs_exponent = d.vhs_exponent;
  o.restitution = dsmc ? d.restitution : m.restitution;
  o.drive = d.drive;
  o.drive_dt = d.drive_dt;
  o.shear_rate = d.shear_rate;
  o.thermostat = d.thermostat;
  o.scheme = d.scheme;
  o.dt = d.dt;
  o.lane_size = d.lane_size;
  o.epoch = d.epoch;
  o.tc_time = m.tc_time;
  o.packing = m.packing;
  o.start_packing = m.start_packing;
  // The run's span and the command's switches.
  o.until = dsmc ? 10.0 : 20.0;
  o.every = 0.0;  // Schedule::default_intervals
  o.histogram_every = 0.0;
  o.trajectory_every = 0.0;
  o.init_file.clear();
  o.init_frame = -1;
  o.equilibration = 0.0;
  o.threads = 1;
  o.replicas = 1;
  o.checkpoint_every = 0.0;
  o.transport = false;
  o.correlation_dt = 0.05;
  o.correlation_time = 40.0;
  o.tagged = 32;
  o.structure = false;
  o.rdf_max = 5.0;
  o.k_max = 15.0;
  return o;
}

void set_text(RunOptions& o, const Option& opt, const std::string& text) {
  const std::string name = cli_name(opt);
  std::visit(
      [&](auto m) {
        using T = std::remove_reference_t<decltype(o.*m)>;
        if constexpr (std::is_same_v<T, double>) set_real(o, opt, parse_number<double>(name, text));
        else if constexpr (std::is_same_v<T, std::uint64_t>)
          set_unsigned(o, opt, parse_number<std::uint64_t>(name, text));
        else if constexpr (std::is_same_v<T, bool>) {
          if (text != "true" && text != "false") reject(name + " is a flag: true or false");
          set_flag(o, opt, text == "true");
        } else if constexpr (std::is_same_v<T, std::string> || Named<T>::value)
          set_string(o, opt, text);
        else set_integer(o, opt, parse_number<long long>(name, text));
      },
      opt.field);
}

void set_integer(RunOptions& o, const Option& opt, long long v) {
  if (std::holds_alternative<std::uint64_t R::*>(opt.field)) {
    if (v < 0) reject(fmt::format("--{} must be {}, got {}", opt.name, opt.range.must, v));
    return set_unsigned(o, opt, static_cast<std::uint64_t>(v));
  }
  check_range(opt, static_cast<double>(v), std::to_string(v));
  if (auto* p = std::get_if<int R::*>(&opt.field)) o.*(*p) = static_cast<int>(v);
  else if (auto* q = std::get_if<long long R::*>(&opt.field)) o.*(*q) = v;
  else wrong_type(opt, "an integer");
  given(o, opt);
}

void set_unsigned(RunOptions& o, const Option& opt, std::uint64_t v) {
  auto* p = std::get_if<std::uint64_t R::*>(&opt.field);
  if (!p) {
    if (v > static_cast<std::uint64_t>(1) << 62) check_range(opt, 1e300, std::to_string(v));
    return set_integer(o, opt, static_cast<long long>(v));
  }
  o.*(*p) = v;
  given(o, opt);
}

void set_real(RunOptions& o, const Option& opt, double v) {
  auto* p = std::get_if<double R::*>(&opt.field);
  if (!p) wrong_type(opt, "a number");
  check_range(opt, v, fmt::format("{}", v));
  o.*(*p) = v;
  given(o, opt);
}

void set_string(RunOptions& o, const Option& opt, const std::string& v) {
  // an error of a check or a name's parse, naming the option once
  const auto named_error = [&](const InvalidInput& e) {
    const std::string what = e.what();
    // parse_duration names the option itself
    reject(what.rfind(cli_name(opt), 0) == 0 ? what : cli_name(opt) + ": " + what);
  };
  const bool named = std::visit(
      [&](auto m) {
        using T = std::remove_reference_t<decltype(o.*m)>;
        if constexpr (Named<T>::value) {
          try {
            o.*m = Named<T>::parse(v);
          } catch (const InvalidInput& e) {
            named_error(e);
          }
          return true;
        } else {
          return false;
        }
      },
      opt.field);
  if (!named) {
    auto* p = std::get_if<std::string R::*>(&opt.field);
    if (!p) wrong_type(opt, "text");
    if (opt.check) {
      try {
        opt.check(v);
      } catch (const InvalidInput& e) {
        named_error(e);
      }
    }
    if (opt.required_cli && v.empty()) reject(cli_name(opt) + " must not be empty");
    o.*(*p) = v;
  }
  given(o, opt);
}

void set_flag(RunOptions& o, const Option& opt, bool v) {
  auto* p = std::get_if<bool R::*>(&opt.field);
  if (!p) wrong_type(opt, "a flag");
  o.*(*p) = v;
  given(o, opt);
}

std::string value_text(const RunOptions& o, const Option& opt) {
  return std::visit(
      [&](auto m) -> std::string {
        const auto& v = o.*m;
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>) return fmt::format("{:.17g}", v);
        else if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::string>) return v;
        else if constexpr (Named<T>::value) return std::string(Named<T>::name(v));
        else return std::to_string(v);
      },
      opt.field);
}

std::string default_text(const Option& opt) {
  if (!opt.unset.empty()) return std::string(opt.unset);
  if (opt.name == "engine") return std::string(registry::name(default_engine));
  // Shortest round-trip form for numbers ("0.1", not "0.10000000000000001").
  const auto shown = [&](const RunOptions& r) {
    if (auto* p = std::get_if<double R::*>(&opt.field)) return fmt::format("{}", r.*(*p));
    return value_text(r, opt);
  };
  const std::string a = shown(defaults(registry::EngineKind::dsmc));
  const std::string b = shown(defaults(registry::EngineKind::edmd));
  if (opt.engines != Engines::both || a == b) return opt.engines == Engines::edmd ? b : a;
  return fmt::format("{} for dsmc, {} for edmd", a, b);
}

std::vector<std::string> replay_arguments(const RunOptions& o) {
  std::vector<std::string> a;
  for (const Option& opt : table) {
    if (opt.name == "out" || opt.name == "json" || !o.was_given(cli_name(opt))) continue;
    a.push_back(cli_name(opt));
    a.push_back(value_text(o, opt));
  }
  return a;
}

}  // namespace hypergas::options
