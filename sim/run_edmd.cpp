// sim/run_edmd.cpp -- `hypergas run --engine edmd`: event-driven MD with recorders.
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "engine_runs.hpp"
#include "granular_summary.hpp"
#include "hypergas/granular/theory.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/engine_concept.hpp"
#include "hypergas/registry.hpp"
#include "run_driver.hpp"
#include "run_observer.hpp"

namespace hypergas::cli {

namespace {

/// Fraction of [0, until] spent equilibrating the lattice start before sampling, and the
/// stops (checkpoint opportunities) in it.
constexpr double equilibration_fraction = 0.2;
constexpr int equilibration_stops = 10;

template <int D, bool Species, class Scan>
RunRecord run(const RunOptions& o, const edmd::Config& cfg, bool progress, RunContext& ctx) {
  constexpr Features F{.positions = true, .species = Species};
  using Engine = edmd::Engine<D, F, Scan>;
  static_assert(SimulationEngine<Engine>);
  using Clock = std::chrono::steady_clock;
  const double until = o.until;
  const double t_eq = equilibration_fraction * until;
  const RunPlan plan{.sampling = o.schedule(t_eq), .warmup_stops = equilibration_stops};
  const double every = plan.sampling.every();

  const auto t0 = Clock::now();
  RunRecord rec;
  rec.vacf = std::make_unique<analysis::VacfRecorder>(std::min<std::size_t>(cfg.n, 2000));
  analysis::VacfRecorder& vacf = *rec.vacf;
  DriverState st;
  Conserved<D> c0;
  std::optional<Engine> e;
  edmd::Config elastic = cfg;
  elastic.restitution = 1.0;  // the equilibration (see Quench below)
  Engine& engine = start_engine(e, elastic, ctx, st, c0, rec.moments, vacf);
  std::vector<Observer*> targets{&rec.moments, &vacf};
  if (o.transport) {
    analysis::TransportSettings ts;
    ts.dt = o.correlation_dt;
    ts.max_lag = o.correlation_time;
    ts.tagged = o.tagged;
    rec.helfand = std::make_unique<analysis::HelfandRecorder>(ts, D, cfg.n, t_eq, until);
    targets.push_back(rec.helfand.get());
  }
  if (o.structure) {
    analysis::StructureSettings ss;
    ss.r_max = o.rdf_max;
    ss.k_max = o.k_max;
    ss.seed = o.seed;
    rec.structure = std::make_unique<analysis::StructureRecorder>(ss, D, cfg.n, t_eq);
    targets.push_back(rec.structure.get());
  }
  // A granular run equilibrates elastically and is quenched after the first sample (at the
  // end of the equilibration): the cooling starts from the equilibrium fluid.
  struct Quench final : Observer {
    Engine& e;
    Observer& next;
    double alpha;
    Quench(Engine& en, Observer& nx, double a) : e(en), next(nx), alpha(a) {}
    void observe(const Snapshot& s) override {
      next.observe(s);
      if (e.restitution() != alpha) e.set_restitution(alpha);
    }
  };
  RunObserver inner(std::move(targets), "edmd", until, progress);
  Quench obs(engine, inner, o.restitution);
  const auto save = [&](checkpoint::Writer& w) {
    save_run(w, o, st, c0, engine, rec.moments, vacf);
  };
  drive(engine, plan, st, obs, ctx.checkpoints, save);
  const auto t2 = Clock::now();
  const auto c1 = conserved(engine.particles());

  const double wall = std::chrono::duration<double>(t2 - t0).count();
  const double engine_s = st.engine_s;
  const auto coll = static_cast<std::int64_t>(engine.collisions());
  const auto last = [&](const char* col) { return rec.moments.column(col).back(); };
  const bool granular = o.restitution != 1.0;
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const double Z = granular ? nan : engine.pressure_Z();  // no equilibrium pressure
  const auto ta = Clock::now();
  if (rec.helfand) rec.helfand->finish();
  if (rec.structure) rec.structure->finish();
  st.analysis_s += std::chrono::duration<double>(Clock::now() - ta).count();
  rec.summary = analysis::JsonObject{
      {"dim", std::int64_t{D}},
      {"engine", std::string(registry::name(registry::EngineKind::edmd))},
      {"model", std::string(dsmc::HardSpheres::name)},
      {"n", static_cast<std::int64_t>(o.n)},
      {"seed", o.seed},  // unsigned 64-bit
      {"collisions", coll},
      {"wall_s", wall},
      {"collisions_per_s", engine_s > 0.0 ? static_cast<double>(coll) / engine_s : 0.0},
      {"energy_rel_drift", granular ? nan : energy_rel_drift(c0, c1)},
      {"momentum_drift", momentum_drift(c0, c1)},
      {"packing", engine.packing()},
      {"scan", std::string(Engine::scan_name)},
      {"Z", Z},
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
      {"engine_s", st.engine_s},
      {"analysis_s", st.analysis_s},
      {"engine_bytes_per_particle", engine.bytes_per_particle()},
      {"peak_rss_bytes_per_particle", peak_rss_bytes() / static_cast<double>(o.n)},
      {"checkpoints", static_cast<std::int64_t>(st.checkpoints)},
      {"resumes", static_cast<std::int64_t>(st.resumes)},
      {"contact_value_from_Z", granular ? nan : edmd::contact_value(D, Z, engine.packing())},
  };
  if (granular) {
    add_granular_summary(rec.summary, rec.moments, GranularRun{D, o.restitution, false, true},
                         false);
    // Haff's t0 of the Enskog gas at the initial temperature (sigma sqrt(m/kT0)), with the
    // contact value of Henderson (2D) or Carnahan-Starling (3D)
    double t0 = nan;
    if ((D == 2 || D == 3) && !Species) {
      const double eta = engine.packing();
      const double chi = D == 2 ? granular::chi_henderson(eta) : granular::chi_carnahan_starling(eta);
      const double a2 = granular::a2_hcs(o.restitution, D);
      t0 = granular::haff_t0(o.restitution, D, a2) /
           granular::enskog_collision_frequency(D, eta, chi);
    }
    rec.summary.emplace_back("haff_t0_enskog", t0);
    rec.summary.emplace_back("tc_elastic_collisions",
                             static_cast<std::int64_t>(engine.tc_elastic_collisions()));
  }
  if (rec.structure) {
    rec.summary.emplace_back("contact_value_rdf", rec.structure->finish().contact);
    rec.summary.emplace_back("contact_value_rdf_error", rec.structure->finish().contact_error);
  }
  if (rec.helfand) {
    rec.summary.emplace_back("transport_mean_free_time", rec.helfand->mean_free_time());
    rec.summary.emplace_back("transport_chi", rec.helfand->chi());
    for (const auto& c : rec.helfand->finish()) {
      rec.summary.emplace_back(c.name, c.value);
      rec.summary.emplace_back(c.name + "_error", c.error);
    }
  }
  return rec;
}

}  // namespace

RunRecord simulate_edmd(const RunOptions& o, bool progress, RunContext& ctx) {
  const edmd::Config cfg = edmd_config(o);
  const bool species = two_species(o);
  // The scan follows the density regime (registry::regime); a checkpoint holds the same
  // packing, so a resumed run gets the scan it was saved with.
  return registry::dispatch(
      [&](auto dim, auto sp, auto dense) {
        constexpr int D = decltype(dim)::type::value;
        using Scan = registry::RegimeScan<typename decltype(dense)::type, D>;
        return run<D, decltype(sp)::type::value, Scan>(o, cfg, progress, ctx);
      },
      registry::dimension(o.dim), registry::species(species),
      registry::regime(o.dim, cfg.packing));
}

}  // namespace hypergas::cli
