// sim/run_edmd.cpp -- `hypergas run --engine edmd`: event-driven MD with recorders.
#include <chrono>
#include <cmath>

#include "engine_runs.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/engine_concept.hpp"
#include "hypergas/registry.hpp"
#include "run_observer.hpp"

namespace hypergas::cli {

namespace {

/// Fraction of [0, until] spent equilibrating the lattice start before sampling.
constexpr double equilibration_fraction = 0.2;

template <int D, bool Species>
RunRecord run(const RunOptions& o, const edmd::Config& cfg, bool progress) {
  constexpr Features F{.positions = true, .species = Species};
  using Clock = std::chrono::steady_clock;
  const double until = o.until > 0.0 ? o.until : 20.0;
  const double t_eq = equilibration_fraction * until;
  const double every = sampling_interval(until - t_eq, o.every);

  const auto t0 = Clock::now();
  static_assert(SimulationEngine<edmd::Engine<D, F>>);
  edmd::Engine<D, F> engine(cfg);
  const auto c0 = conserved(engine.particles());
  const auto t1 = Clock::now();
  engine.run_until(t_eq);
  engine.reset_observables();
  RunRecord rec;
  rec.vacf = std::make_unique<analysis::VacfRecorder>(std::min<std::size_t>(cfg.n, 2000));
  analysis::VacfRecorder& vacf = *rec.vacf;
  RunObserver obs({&rec.moments, &vacf}, "edmd", until, progress);
  engine.run_until(until, &obs, every);
  const auto t2 = Clock::now();
  const auto c1 = conserved(engine.particles());

  const double wall = std::chrono::duration<double>(t2 - t0).count();
  const double engine_s = std::chrono::duration<double>(t2 - t1).count() - obs.analysis_seconds();
  const auto coll = static_cast<std::int64_t>(engine.collisions());
  const auto last = [&](const char* col) { return rec.moments.column(col).back(); };
  rec.summary = analysis::JsonObject{
      {"dim", std::int64_t{D}},
      {"engine", std::string(registry::name(registry::EngineKind::edmd))},
      {"model", std::string(dsmc::HardSpheres::name)},
      {"n", static_cast<std::int64_t>(o.n)},
      {"seed", static_cast<std::int64_t>(o.seed)},
      {"collisions", coll},
      {"wall_s", wall},
      {"collisions_per_s", engine_s > 0.0 ? static_cast<double>(coll) / engine_s : 0.0},
      {"energy_rel_drift", energy_rel_drift(c0, c1)},
      {"momentum_drift", momentum_drift(c0, c1)},
      {"packing", engine.packing()},
      {"Z", engine.pressure_Z()},
      {"collision_rate", engine.collision_rate()},
      {"mean_free_time", engine.mean_free_time()},
      {"init", std::string(registry::name(o.initial_state()))},
      {"time", engine.time()},
      {"equilibration_time", t_eq},
      {"every", every},
      {"mass_ratio", o.mass_ratio},
      {"fraction", Species ? o.fraction : 0.0},
      {"kT", engine.temperature()},
      {"diffusion_green_kubo", vacf.frames() >= 2 ? vacf.green_kubo() : 0.0},
      {"kurtosis_x", last("kurtosis_x")},
      {"ks_p_speed", last("ks_p_speed")},
  };
  return rec;
}

}  // namespace

RunRecord simulate_edmd(const RunOptions& o, bool progress) {
  edmd::Config cfg;
  cfg.n = static_cast<std::size_t>(o.n);
  cfg.packing = o.packing;
  cfg.seed = o.seed;
  cfg.init = o.initial_state();
  cfg.initial.kT = 1.0;
  cfg.initial.fraction = o.fraction;
  cfg.initial.mass_ratio = o.mass_ratio;
  const bool species = o.mass_ratio != 1.0;
  return registry::dispatch(
      [&](auto dim, auto sp) {
        return run<decltype(dim)::type::value, decltype(sp)::type::value>(o, cfg, progress);
      },
      registry::dimension(o.dim), registry::species(species));
}

}  // namespace hypergas::cli
