// sim/run_dsmc.cpp -- `hypergas run --engine dsmc`: the velocity-space engine with recorders.
#include <chrono>
#include <cmath>
#include <limits>
#include <variant>

#include <fmt/core.h>

#include "dispatch.hpp"
#include "engine_runs.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "run_observer.hpp"

namespace hypergas::cli {

double sampling_interval(double span, double every) {
  if (!(every > 0.0)) return span / 50.0;
  const double k = std::max(1.0, std::round(span / every));
  return span / k;
}

RunRecord simulate(const RunOptions& o, bool progress) {
#ifdef HYPERGAS_CLI_EDMD
  if (o.engine_kind() == EngineKind::edmd) return simulate_edmd(o, progress);
#else
  if (o.engine_kind() == EngineKind::edmd)
    throw InvalidInput("--engine edmd: the EDMD engine is not part of this build yet");
#endif
  return simulate_dsmc(o, progress);
}

std::string summary_field(const analysis::JsonObject& o, const std::string& key) {
  for (const auto& [k, v] : o)
    if (k == key)
      return std::visit(
          [](const auto& x) -> std::string {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, std::string>) return x;
            else if constexpr (std::is_same_v<T, double>) return fmt::format("{:.4g}", x);
            else return fmt::format("{}", x);
          },
          v);
  return "-";
}

double summary_number(const analysis::JsonObject& o, const std::string& key) {
  for (const auto& [k, v] : o)
    if (k == key) {
      if (const auto* d = std::get_if<double>(&v)) return *d;
      if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
    }
  return std::numeric_limits<double>::quiet_NaN();
}

namespace {

template <int D, class Model, bool Species>
RunRecord run(const RunOptions& o, const dsmc::Config& cfg, bool progress) {
  constexpr Features F{.species = Species};
  using Clock = std::chrono::steady_clock;
  const double until = o.until > 0.0 ? o.until : 10.0;
  const double every = sampling_interval(until, o.every);

  const auto t0 = Clock::now();
  dsmc::Engine<D, Model, F> engine(cfg);
  const Conserved c0 = conserved(engine.particles());
  RunRecord rec;
  RunObserver obs({&rec.moments}, "dsmc", until, progress);
  const auto t1 = Clock::now();
  engine.run_until(until, &obs, every);
  const auto t2 = Clock::now();
  const Conserved c1 = conserved(engine.particles());

  const double wall = std::chrono::duration<double>(t2 - t0).count();
  const double engine_s = std::chrono::duration<double>(t2 - t1).count() - obs.analysis_seconds();
  const auto coll = static_cast<std::int64_t>(engine.collisions());
  const auto last = [&](const char* col) { return rec.moments.column(col).back(); };
  rec.summary = analysis::JsonObject{
      {"dim", std::int64_t{D}},
      {"engine", std::string("dsmc")},
      {"model", o.model},
      {"n", static_cast<std::int64_t>(o.n)},
      {"seed", static_cast<std::int64_t>(o.seed)},
      {"collisions", coll},
      {"wall_s", wall},
      {"collisions_per_s", engine_s > 0.0 ? static_cast<double>(coll) / engine_s : 0.0},
      {"energy_rel_drift", energy_rel_drift(c0, c1)},
      {"momentum_drift", momentum_drift(c0, c1)},
      {"init", o.init.empty() ? default_init(EngineKind::dsmc) : o.init},
      {"time", engine.time()},
      {"every", every},
      {"mass_ratio", o.mass_ratio},
      {"fraction", Species ? o.fraction : 0.0},
      {"collisions_per_particle", engine.collisions_per_particle()},
      {"kurtosis_x", last("kurtosis_x")},
      {"m4_ratio", last("m4_ratio")},
      {"l1_speed", last("l1_speed")},
      {"ks_p_speed", last("ks_p_speed")},
      {"chi2_p_speed", last("chi2_p_speed")},
  };
  return rec;
}

}  // namespace

RunRecord simulate_dsmc(const RunOptions& o, bool progress) {
  dsmc::Config cfg;
  cfg.n = static_cast<std::size_t>(o.n);
  cfg.model = dsmc::parse_model(o.model);
  cfg.vhs_exponent = o.vhs_exponent;
  cfg.seed = o.seed;
  cfg.init = parse_initial_state(o.init.empty() ? default_init(EngineKind::dsmc) : o.init);
  cfg.initial.kT = o.temperature;
  cfg.initial.fraction = o.fraction;
  cfg.initial.mass_ratio = o.mass_ratio;
  const bool species = o.mass_ratio != 1.0;
  if (o.dim == 1 && !species)
    fmt::print(stderr,
               "hypergas: note: in D = 1 equal masses only swap velocities, so the gas never "
               "relaxes; use --mass-ratio R (R != 1) for a two-mass gas\n");
  return dispatch_dim(o.dim, [&](auto d) {
    return dispatch_model(cfg.model, [&](auto model) {
      return dispatch_bool(species, [&](auto sp) {
        return run<decltype(d)::value, typename decltype(model)::type, decltype(sp)::value>(
            o, cfg, progress);
      });
    });
  });
}

}  // namespace hypergas::cli
