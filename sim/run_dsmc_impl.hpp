// sim/run_dsmc_impl.hpp -- the DSMC run for one (D, model, species): the body of
// `hypergas run --engine dsmc`. Its 36 instantiations are compiled in three files
// (run_dsmc_d12.cpp, _d34, _d56) so that a parallel build spreads them over the cores;
// run_dsmc.cpp dispatches to them.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include <fmt/core.h>

#include "engine_runs.hpp"
#include "granular_summary.hpp"
#include "hypergas/analysis/estimates.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/engine_concept.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/studies/replicas.hpp"
#include "run_driver.hpp"
#include "run_observer.hpp"

namespace hypergas::cli::detail {

/// --transport: the fine grid of the plan (substeps of about --correlation-dt) and the
/// recorder, with the samples it will take (the fine stops from transport_warmup on).
template <int D>
inline std::unique_ptr<analysis::TransportRecorder> transport_recorder(const RunOptions& o,
                                                                RunPlan& plan) {
  const double every = plan.sampling.every();
  plan.substeps = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::llround(every / o.correlation_dt)));
  const double dt = every / static_cast<double>(plan.substeps);
  std::uint64_t frames = 0;
  for (std::uint64_t k = 0;; ++k) {
    const std::optional<Stop> s = plan.stop(k);
    if (!s) break;
    frames += s->time >= options::transport_warmup - 1e-9 * options::transport_warmup;
  }
  analysis::TransportSettings ts;
  ts.dt = dt;
  ts.max_lag = o.correlation_time;
  ts.tagged = o.tagged;
  ts.warmup = options::transport_warmup;
  ts.seed = o.seed;
  const registry::ModelTraits m = registry::model_traits(o.model, o.vhs_exponent);
  return std::make_unique<analysis::TransportRecorder>(
      ts, D, static_cast<std::size_t>(o.n), frames,
      analysis::CollisionLaw{m.exponent, m.isotropic_scattering});
}

/// Runs one system on o.threads threads (checkpoints and resume through ctx) or `replicas`
/// independent replicas (studies/replicas.hpp: replica 0 keeps the seed, so its files equal
/// those of a one-replica run; the replicas run side by side, one per thread, with
/// --threads 1, else one after another, each on o.threads threads). The files come from replica 0; the summary adds totals, the aggregate
/// rate and the replica mean of the final kurtosis with its error.
template <int D, class Model, bool Species>
RunRecord run_dsmc(const RunOptions& o, const dsmc::Config& cfg, bool progress,
                   RunContext& ctx) {
  constexpr Features F{.species = Species};
  using Engine = dsmc::Engine<D, Model, F>;
  static_assert(SimulationEngine<Engine>);
  using Clock = std::chrono::steady_clock;
  const double until = o.until;
  RunPlan plan{.sampling = o.schedule(0.0), .warmup_stops = 0};
  const double every = plan.sampling.every();
  const int k = o.replicas;
  std::unique_ptr<analysis::TransportRecorder> transport;
  if (o.transport) transport = transport_recorder<D>(o, plan);

  std::vector<RunRecord> recs(static_cast<std::size_t>(k));
  // per replica; under MPI (studies::ReplicaSpread) these reach rank 0 from every rank
  std::vector<double> engine_s(k), rate(k), drift_e(k), drift_p(k), cpp(k), coll(k), kurt(k);
  DriverState st0;
  double engine_bpp = 0.0;
  const auto t0 = Clock::now();
  const auto body = [&](int r, Engine& engine, DriverState& st, const Conserved<D>& c0,
                        Checkpointer& ck) {
    engine.set_threads(o.threads);
    recs[r].moments.set_threads(o.threads);
    RunObserver obs({&recs[r].moments}, "dsmc", until, progress && r == 0);
    const auto save = [&](checkpoint::Writer& w) {
      save_run(w, o, st, c0, engine, recs[r].moments);
    };
    drive(engine, plan, st, obs, ck, save, r == 0 ? transport.get() : nullptr);
    const auto c1 = conserved(engine.particles());
    engine_s[r] = st.engine_s;
    coll[r] = static_cast<double>(engine.collisions());  // exact below 2^53
    rate[r] = engine_s[r] > 0.0 ? coll[r] / engine_s[r] : 0.0;
    drift_e[r] = energy_rel_drift(c0, c1);
    drift_p[r] = momentum_drift(c0, c1);
    cpp[r] = engine.collisions_per_particle();
    kurt[r] = recs[r].moments.column("kurtosis_x").back();
    if (r == 0) engine_bpp = engine.bytes_per_particle();
  };
  if (k == 1) {
    std::optional<Engine> engine;
    Conserved<D> c0;
    body(0, start_engine(engine, cfg, ctx, st0, c0, recs[0].moments), st0, c0, ctx.checkpoints);
  } else {
    studies::run_replicas<Engine>(
        cfg, k, o.threads == 1 ? k : 1,
        [&](int r, Engine& engine) {
          DriverState st;
          Checkpointer none;
          body(r, engine, r == 0 ? st0 : st, conserved(engine.particles()), none);
        },
        {&engine_s, &rate, &drift_e, &drift_p, &cpp, &coll, &kurt});
    // replica 0 ran on rank 0, which writes the files; the other ranks are done
    if (!studies::replica_root()) return std::move(recs[0]);
  }
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();

  RunRecord rec = std::move(recs[0]);
  if (transport) {
    const auto ta = Clock::now();
    transport->finish();
    st0.analysis_s += std::chrono::duration<double>(Clock::now() - ta).count();
  }
  std::int64_t total = 0;
  double total_rate = 0.0;
  for (int r = 0; r < k; ++r) {
    total += static_cast<std::int64_t>(coll[r]);
    total_rate += rate[r];
  }
  // one replica has no standard error (NaN, analysis/estimates.hpp); its summary says 0
  const auto [kurt_mean, kurt_se_k] = analysis::mean_se(kurt);
  const double kurt_se = k == 1 ? 0.0 : kurt_se_k;
  const auto last = [&](const char* col) { return rec.moments.column(col).back(); };
  rec.summary = analysis::JsonObject{
      {"dim", std::int64_t{D}},
      {"engine", std::string(registry::name(registry::EngineKind::dsmc))},
      {"model", o.model},
      {"n", static_cast<std::int64_t>(o.n)},
      {"seed", o.seed},  // unsigned 64-bit: seeds of replicas are often above 2^63
      {"collisions", total},
      {"wall_s", wall},
      {"collisions_per_s", total_rate},
      // a granular gas loses its energy: no drift to report
      {"energy_rel_drift", o.restitution != 1.0 ? std::numeric_limits<double>::quiet_NaN()
                                                : *std::max_element(drift_e.begin(), drift_e.end())},
      {"momentum_drift", *std::max_element(drift_p.begin(), drift_p.end())},
      {"init", std::string(registry::name(o.initial_state()))},
      {"time", until},
      {"every", every},
      {"mass_ratio", o.mass_ratio},
      {"fraction", Species ? o.fraction : 0.0},
      {"replicas", std::int64_t{k}},
      {"threads", std::int64_t{o.threads}},
      {"collisions_per_particle", cpp[0]},
      {"kurtosis_x", last("kurtosis_x")},
      {"m4_ratio", last("m4_ratio")},
      {"l1_speed", last("l1_speed")},
      {"ks_p_speed", last("ks_p_speed")},
      {"chi2_p_speed", last("chi2_p_speed")},
      {"kurtosis_x_replica_mean", kurt_mean},
      {"kurtosis_x_replica_se", kurt_se},
      {"engine_s", st0.engine_s},
      {"analysis_s", st0.analysis_s},
      {"engine_bytes_per_particle", engine_bpp},
      {"peak_rss_bytes_per_particle", peak_rss_bytes() / static_cast<double>(o.n)},
      {"checkpoints", static_cast<std::int64_t>(st0.checkpoints)},
      {"resumes", static_cast<std::int64_t>(st0.resumes)},
  };
  if (o.restitution != 1.0)
    add_granular_summary(rec.summary, rec.moments,
                         GranularRun{D, o.restitution, cfg.drive != dsmc::Drive::none,
                                     std::is_same_v<Model, dsmc::HardSpheres>},
                         true);
  if (transport) {
    rec.summary.emplace_back("transport_dt", transport->dt());
    rec.summary.emplace_back("transport_samples", static_cast<std::int64_t>(transport->frames()));
    for (const auto& c : transport->finish()) {
      rec.summary.emplace_back(c.name, c.value);
      rec.summary.emplace_back(c.name + "_error", c.error);
      rec.summary.emplace_back(c.name + "_ratio", c.ratio);
      rec.summary.emplace_back(c.name + "_ratio_error", c.ratio_error);
    }
    rec.transport = std::move(transport);
  }
  return rec;
}

}  // namespace hypergas::cli::detail

/// Explicit instantiations of run_dsmc for dimension D, every model and both species
/// settings (in the file that defines HYPERGAS_RUN_DSMC_DIMS).
#define HYPERGAS_RUN_DSMC_INSTANTIATE(D)                                                     \
  template RunRecord run_dsmc<D, dsmc::HardSpheres, false>(const RunOptions&,               \
                                                           const dsmc::Config&, bool,        \
                                                           RunContext&);                     \
  template RunRecord run_dsmc<D, dsmc::HardSpheres, true>(const RunOptions&,                \
                                                          const dsmc::Config&, bool,         \
                                                          RunContext&);                      \
  template RunRecord run_dsmc<D, dsmc::MaxwellMolecules, false>(                            \
      const RunOptions&, const dsmc::Config&, bool, RunContext&);                            \
  template RunRecord run_dsmc<D, dsmc::MaxwellMolecules, true>(                             \
      const RunOptions&, const dsmc::Config&, bool, RunContext&);                            \
  template RunRecord run_dsmc<D, dsmc::VariableHardSpheres, false>(                         \
      const RunOptions&, const dsmc::Config&, bool, RunContext&);                            \
  template RunRecord run_dsmc<D, dsmc::VariableHardSpheres, true>(                          \
      const RunOptions&, const dsmc::Config&, bool, RunContext&);
