// sim/run_edmd.hpp -- the body of `hypergas run --engine edmd` for one engine type (sigma =
// m = kT = 1), compiled in run_dim.cpp.in's translation units. The lattice start
// equilibrates without sampling until sampling_start (--equilibration, by default the first
// fifth of [0, until]); the outputs, Z and the rates come from the rest.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <fmt/core.h>

#include "engine_runs.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/edmd/lattice.hpp"
#include "hypergas/engine_concept.hpp"
#include "hypergas/geometry.hpp"
#include "run_driver.hpp"
#include "run_observer.hpp"
#include "run_summary.hpp"

namespace hypergas::cli::detail {

/// The freezing packing of hard spheres in D dimensions, where the fluid's coexistence with
/// the solid begins (van Meel, Charbonneau, Fortini, Charbonneau, Phys. Rev. E 80, 061110
/// (2009); 2D: the liquid-hexatic transition); 0 in 1D, which does not freeze.
inline double edmd_freezing_packing(int d) {
  switch (d) {
    case 2: return 0.70;
    case 3: return 0.494;
    case 4: return 0.288;
    case 5: return 0.166;
    case 6: return 0.0996;
    default: return 0.0;
  }
}

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
  plan.substeps = plan_substeps(o, registry::EngineKind::edmd, plan.sampling);
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
  // What the lattice start became (edmd/state.hpp): site gaps below 10 % of a diameter, or
  // --start-packing, start the diameters smaller and compress them to --packing. Above the
  // freezing packing a full lattice stays a crystal, one with vacancies compresses into a
  // glass. The rule is that of edmd::State::setup, recomputed from the options.
  const double freezing = edmd_freezing_packing(D);
  if (o.init_file.empty() && progress && !ctx.resume) {
    const double box = std::pow(static_cast<double>(o.n) * ball_volume(D, 1.0) / o.packing,
                                1.0 / D);
    const double a = box / static_cast<double>(side);
    const double fit = D >= 3 ? a * std::sqrt(2.0) : a;
    double scale = fit >= 1.1 ? 1.0 : 0.9 * fit;
    if (o.was_given("--start-packing") && o.start_packing > 0.0)
      scale = std::min(scale, std::pow(o.start_packing / o.packing, 1.0 / D));
    if (scale < 1.0) {
      const bool above = freezing > 0.0 && o.packing > freezing;
      fmt::print(stderr,
                 "hypergas: note: the start is the lattice{} at packing {:.3g}, compressed to "
                 "{}: {}\n",
                 vacancies > 0 ? " with its vacancies" : "", o.packing * std::pow(scale, D),
                 o.packing,
                 !above          ? "below freezing it melts into the fluid"
                 : vacancies > 0 ? "above freezing, with vacancies, it compresses into a "
                                   "glass, not a crystal (a full lattice stays one)"
                                 : "above freezing the full lattice stays a crystal");
    } else if (vacancies > 0) {
      fmt::print(stderr, "hypergas: note: the start is the lattice with its vacancies at "
                         "packing {}\n", o.packing);
    }
  }
  if (freezing > 0.0 && o.packing > freezing && progress && !ctx.resume)
    fmt::print(stderr,
               "hypergas: note: packing {} is above the freezing packing {} of hard spheres "
               "in D = {} (van Meel et al., Phys. Rev. E 80, 061110 (2009)): the equilibrium "
               "state there is a solid, a fluid is metastable\n",
               o.packing, freezing, D);
  RunObserver obs(samplers(rec.outputs), "edmd", until, progress);
  const auto save = [&](checkpoint::Writer& w) { save_run(w, o, st, c0, engine, rec.outputs); };
  FanOut fine(fine_observers(rec.outputs));
  drive(engine, plan, st, obs, ctx.checkpoints, save, fine.empty() ? nullptr : &fine);
  const auto t2 = Clock::now();
  const auto c1 = conserved(engine.particles());

  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const bool sheared = o.shear_rate != 0.0;
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
  // the engine's facts (edmd::Engine::describe), then the lattice start's
  analysis::JsonObject keys = engine_facts(engine);
  keys.emplace_back("equilibration_time", t_eq);
  keys.emplace_back("lattice_sites", sites);
  keys.emplace_back("vacancies", vacancies);
  rec.summary = run_summary(o, f, keys, st);
  summarize_outputs(rec.outputs, rec.summary);
  return rec;
}

}  // namespace hypergas::cli::detail
