// sim/run_dsmc.hpp -- the body of `hypergas run --engine dsmc` for one engine type (time in
// equilibrium mean collision times), compiled in run_dim.cpp.in's translation units.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <fmt/core.h>

#include "engine_runs.hpp"
#include "hypergas/analysis/estimates.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/engine_concept.hpp"
#include "hypergas/studies/replicas.hpp"
#include "run_driver.hpp"
#include "run_observer.hpp"
#include "run_summary.hpp"

namespace hypergas::cli::detail {

/// Runs one system on o.threads threads (checkpoints and resume through ctx) or `replicas`
/// independent replicas (studies/replicas.hpp: replica 0 keeps the seed, so its files equal
/// those of a one-replica run; the replicas run side by side, one per thread, with
/// --threads 1, else one after another, each on o.threads threads). The outputs are replica
/// 0's; the other replicas keep their own moments only. The summary adds totals, the
/// aggregate rate and the replica means of the final kurtosis and KS p-value with their
/// standard errors (analysis::mean_se), which `run` prints for K > 1.
template <class Engine>
RunRecord run_dsmc(const RunOptions& o, bool progress, RunContext& ctx) {
  static_assert(SimulationEngine<Engine>);
  using Clock = std::chrono::steady_clock;
  const dsmc::Config cfg = dsmc_config(o);
  const double until = o.until;
  RunPlan plan{.sampling = o.schedule(0.0), .warmup_stops = 0, .substeps = 1, .quench = {}};
  plan.substeps = plan_substeps(o, registry::EngineKind::dsmc, plan.sampling);
  const double every = plan.sampling.every();
  const int k = o.replicas;
  const RunSetup setup{o, registry::EngineKind::dsmc, plan, 0.0};
  RunRecord rec;
  rec.outputs = make_outputs(setup);
  std::vector<std::unique_ptr<MomentsOutput>> others(static_cast<std::size_t>(k));
  for (int r = 1; r < k; ++r) others[r] = std::make_unique<MomentsOutput>(setup);
  const auto moments = [&](int r) -> const MomentsOutput& {
    return r == 0 ? rec.moments() : *others[r];
  };

  // per replica; under MPI (studies::ReplicaSpread) these reach rank 0 from every rank
  std::vector<double> engine_s(k), rate(k), drift_e(k), drift_p(k), coll(k), kurt(k),
      ks(k);
  DriverState st0;
  double engine_bpp = 0.0, setup_s = 0.0;
  analysis::JsonObject engine_keys;  // replica 0's engine's facts (dsmc::Engine::describe)
  const auto t0 = Clock::now();
  const auto body = [&](int r, Engine& engine, DriverState& st, const Conserved<Engine::dim>& c0,
                        Checkpointer& ck) {
    // the engine is made (or restored): what came before the first collision
    if (r == 0) setup_s = std::chrono::duration<double>(Clock::now() - t0).count();
    engine.set_threads(o.threads);
    RunObserver obs(r == 0 ? samplers(rec.outputs) : std::vector<Observer*>{others[r]->sampler()},
                    "dsmc", until, progress && r == 0);
    FanOut fine(r == 0 ? fine_observers(rec.outputs) : std::vector<Observer*>{});
    const auto save = [&](checkpoint::Writer& w) { save_run(w, o, st, c0, engine, rec.outputs); };
    drive(engine, plan, st, obs, ck, save, fine.empty() ? nullptr : &fine);
    const auto c1 = conserved(engine.particles());
    engine_s[r] = st.engine_s;
    coll[r] = static_cast<double>(engine.collisions());  // exact below 2^53
    rate[r] = engine_s[r] > 0.0 ? coll[r] / engine_s[r] : 0.0;
    drift_e[r] = energy_rel_drift(c0, c1);
    drift_p[r] = momentum_drift(c0, c1);
    kurt[r] = moments(r).last("kurtosis_x");
    ks[r] = moments(r).last("ks_p_speed");
    if (r == 0) {
      engine_bpp = engine.bytes_per_particle();
      engine_keys = engine_facts(engine);
    }
  };
  if (k == 1) {
    std::optional<Engine> engine;
    Conserved<Engine::dim> c0;
    {
      const SetupLine line(fmt::format("dsmc: setting up {} particles ({} velocities)", o.n,
                                       registry::name(o.init)),
                           progress && !ctx.resume);
      start_engine(engine, cfg, ctx, st0, c0, rec.outputs, o);
    }
    body(0, *engine, st0, c0, ctx.checkpoints);
  } else {
    studies::run_replicas<Engine>(
        cfg, k, o.threads == 1 ? k : 1,
        [&](int r, Engine& engine) {
          DriverState st;
          Checkpointer none;
          body(r, engine, r == 0 ? st0 : st, conserved(engine.particles()), none);
        },
        {&engine_s, &rate, &drift_e, &drift_p, &coll, &kurt, &ks});
    // replica 0 ran on rank 0, which writes the files; the other ranks are done
    if (!studies::replica_root()) return rec;
  }
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  finish_outputs(rec.outputs, st0);

  RunFacts f;
  f.dim = Engine::dim;
  f.model = o.model;
  for (int r = 0; r < k; ++r) {
    f.collisions += static_cast<std::int64_t>(coll[r]);
    f.collisions_per_s += rate[r];
  }
  f.wall_s = wall;
  // a granular gas loses its energy, one sheared without thermostat gains it: no drift to
  // report (the isokinetic thermostat holds it: its drift is reported)
  const bool energy_held =
      o.restitution == 1.0 &&
      (o.shear_rate == 0.0 || o.thermostat == dsmc::Thermostat::isokinetic);
  f.energy_rel_drift = !energy_held ? std::numeric_limits<double>::quiet_NaN()
                                            : *std::max_element(drift_e.begin(), drift_e.end());
  f.momentum_drift = *std::max_element(drift_p.begin(), drift_p.end());
  f.time = until;
  f.every = every;
  f.fraction = two_species(o) ? o.fraction : 0.0;
  f.engine_bytes_per_particle = engine_bpp;
  f.setup_s = setup_s;
  // one replica has no standard error (NaN, analysis/estimates.hpp); its summary says 0
  const auto [kurt_mean, kurt_se_k] = analysis::mean_se(kurt);
  const double kurt_se = k == 1 ? 0.0 : kurt_se_k;
  const auto [ks_mean, ks_se_k] = analysis::mean_se(ks);
  const double ks_se = k == 1 ? 0.0 : ks_se_k;
  analysis::JsonObject keys{{"replicas", std::int64_t{k}},
                            {"threads", std::int64_t{o.threads}},
                            {"scheme", std::string(registry::name(o.scheme))}};
  keys.insert(keys.end(), engine_keys.begin(), engine_keys.end());
  keys.emplace_back("kurtosis_x_replica_mean", kurt_mean);
  keys.emplace_back("kurtosis_x_replica_se", kurt_se);
  keys.emplace_back("ks_p_speed_replica_mean", ks_mean);
  keys.emplace_back("ks_p_speed_replica_se", ks_se);
  rec.summary = run_summary(o, f, keys, st0);
  summarize_outputs(rec.outputs, rec.summary);
  return rec;
}

}  // namespace hypergas::cli::detail
