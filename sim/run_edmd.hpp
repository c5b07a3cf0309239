// sim/run_edmd.hpp -- the body of `hypergas run --engine edmd` for one engine type (sigma =
// m = kT = 1), compiled in run_dim.cpp.in's translation units. The lattice start
// equilibrates without sampling until sampling_start (--equilibration, by default the first
// fifth of [0, until]); the outputs, Z and the rates come from the rest.
#pragma once

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <fmt/core.h>

#include "engine_runs.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/edmd/lattice.hpp"
#include "hypergas/edmd/observables.hpp"
#include "hypergas/engine_concept.hpp"
#include "hypergas/granular/theory.hpp"
#include "run_driver.hpp"
#include "run_observer.hpp"
#include "run_summary.hpp"

namespace hypergas::cli::detail {

/// The stops (checkpoint opportunities) in the equilibration of the lattice start, which
/// ends where sampling starts (sampling_start, engine_runs.hpp).
inline constexpr int equilibration_stops = 10;

template <class Engine>
RunRecord run_edmd(const RunOptions& o, bool progress, RunContext& ctx) {
  static_assert(SimulationEngine<Engine>);
  constexpr int D = Engine::dim;
  using Clock = std::chrono::steady_clock;
  const edmd::Config cfg = edmd_config(o);
  const double until = o.until;
  const double t_eq = sampling_start(o);
  RunPlan plan{.sampling = o.schedule(t_eq), .warmup_stops = equilibration_stops, .substeps = 1,
               .quench = {}};
  const bool granular = o.restitution != 1.0;
  // a granular run equilibrates elastically and is quenched at the end of the equilibration
  if (granular) plan.quench = o.restitution;
  const double every = plan.sampling.every();

  const auto t0 = Clock::now();
  RunRecord rec;
  rec.outputs = make_outputs(RunSetup{o, registry::EngineKind::edmd, plan, t_eq});
  DriverState st;
  Conserved<D> c0;
  std::optional<Engine> e;
  edmd::Config elastic = cfg;
  elastic.restitution = 1.0;  // the equilibration
  Engine& engine = [&]() -> Engine& {
    const SetupLine line(
        o.init_file.empty()
            ? fmt::format("edmd: setting up {} particles at packing {} (lattice start{})", o.n,
                          o.packing, o.was_given("--start-packing") ? ", compression" : "")
            : fmt::format("edmd: reading {} particles at packing {:.6g} from {}", o.n,
                          o.packing, o.init_file),
        progress && !ctx.resume);
    return start_engine(e, elastic, ctx, st, c0, rec.outputs, o);
  }();
  const double setup_s = std::chrono::duration<double>(Clock::now() - t0).count();
  // a lattice start with vacancies (N below the lattice's sites) is said, not hidden
  const std::uint64_t side = edmd::lattice_side(D, static_cast<std::size_t>(o.n));
  const auto sites = static_cast<std::int64_t>(edmd::lattice_capacity(D, side));
  const std::int64_t vacancies = sites - static_cast<std::int64_t>(o.n);
  if (vacancies > 0 && progress && !ctx.resume) {
    const std::uint64_t step = D >= 3 ? 2 : 1;
    std::string fill = fmt::format("{}", sites);
    if (side > step)
      fill = fmt::format("{} or {}", edmd::lattice_capacity(D, side - step), sites);
    fmt::print(stderr,
               "hypergas: note: {} particles start on a lattice of {} sites ({} vacancies, "
               "{:.1f} %); N = {} fill a lattice in D = {}\n",
               o.n, sites, vacancies, 100.0 * static_cast<double>(vacancies) / sites, fill, D);
  }
  RunObserver obs(samplers(rec.outputs), "edmd", until, progress);
  const auto save = [&](checkpoint::Writer& w) { save_run(w, o, st, c0, engine, rec.outputs); };
  FanOut fine(fine_observers(rec.outputs));
  drive(engine, plan, st, obs, ctx.checkpoints, save, fine.empty() ? nullptr : &fine);
  const auto t2 = Clock::now();
  const auto c1 = conserved(engine.particles());

  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const bool sheared = o.shear_rate != 0.0;
  // no equilibrium pressure in a granular or a sheared gas
  const double Z = granular || sheared ? nan : engine.pressure_Z();
  finish_outputs(rec.outputs, st);
  RunFacts f;
  f.dim = D;
  f.model = std::string(dsmc::HardSpheres::name);
  f.collisions = static_cast<std::int64_t>(engine.collisions());
  f.wall_s = std::chrono::duration<double>(t2 - t0).count();
  f.collisions_per_s =
      st.engine_s > 0.0 ? static_cast<double>(f.collisions) / st.engine_s : 0.0;
  f.energy_rel_drift = granular || sheared ? nan : energy_rel_drift(c0, c1);
  // the Lees-Edwards faces change the lab momentum (a particle through the top loses a L m)
  f.momentum_drift = sheared ? nan : momentum_drift(c0, c1);
  f.time = engine.time();
  f.every = every;
  f.fraction = two_species(o) ? o.fraction : 0.0;
  f.engine_bytes_per_particle = engine.bytes_per_particle();
  f.setup_s = setup_s;
  analysis::JsonObject keys{
      {"packing", engine.packing()},
      {"scan", std::string(Engine::scan_name)},
      {"Z", Z},
      {"collision_rate", engine.collision_rate()},
      {"mean_free_time", engine.mean_free_time()},
      {"equilibration_time", t_eq},
      {"kT", engine.temperature()},
      {"contact_value_from_Z", granular ? nan : edmd::contact_value(D, Z, engine.packing())},
      {"lattice_sites", sites},
      {"vacancies", vacancies},
  };
  if (sheared) {
    // the exact balance E(t) = E(0) - a V int P_xy dt (- thermostat, - inelastic loss):
    // its largest deviation
    keys.emplace_back("energy_balance_residual", engine.energy_balance_residual());
    keys.emplace_back("ideal_collision_rate", engine.lees_edwards().nu0);
  }
  if (granular) {
    // Haff's t0 of the Enskog gas at the initial temperature (sigma sqrt(m/kT0)), with the
    // contact value of Henderson (2D) or Carnahan-Starling (3D)
    double haff = nan;
    if ((D == 2 || D == 3) && !two_species(o)) {
      const double eta = engine.packing();
      const double chi =
          D == 2 ? granular::chi_henderson(eta) : granular::chi_carnahan_starling(eta);
      const double a2 = granular::a2_hcs(o.restitution, D);
      haff = granular::haff_t0(o.restitution, D, a2) /
             granular::enskog_collision_frequency(D, eta, chi);
    }
    keys.emplace_back("haff_t0_enskog", haff);
    keys.emplace_back("tc_elastic_collisions",
                      static_cast<std::int64_t>(engine.tc_elastic_collisions()));
  }
  rec.summary = run_summary(o, f, keys, st);
  summarize_outputs(rec.outputs, rec.summary);
  return rec;
}

}  // namespace hypergas::cli::detail
