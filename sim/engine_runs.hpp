// sim/engine_runs.hpp -- one run of an engine, as `hypergas run` and the default scene use it.
//
// `simulate` instantiates the engine for the requested (D, model, features) through
// registry::dispatch (hypergas/registry.hpp), runs it with the analysis recorders attached
// and returns the recorders and the summary fields; the callers decide which files to
// write. All engine template instantiations of the command live in run_dsmc.cpp and
// run_edmd.cpp.
#pragma once

#include <memory>
#include <optional>

#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/helfand_recorder.hpp"
#include "hypergas/analysis/structure_recorder.hpp"
#include "hypergas/analysis/transport_recorder.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "hypergas/conserved.hpp"
#include "options.hpp"
#include "run_driver.hpp"

namespace hypergas::cli {

/// What one engine run produced.
struct RunRecord {
  analysis::MomentsRecorder moments;              ///< one row per sampling time
  std::unique_ptr<analysis::VacfRecorder> vacf;   ///< EDMD only (nullptr for DSMC)
  /// DSMC with --transport: the Green-Kubo coefficients, finished (else nullptr)
  std::unique_ptr<analysis::TransportRecorder> transport;
  /// EDMD with --transport: Einstein-Helfand and Green-Kubo coefficients, finished
  std::unique_ptr<analysis::HelfandRecorder> helfand;
  /// EDMD with --structure: g(r) and S(k), finished
  std::unique_ptr<analysis::StructureRecorder> structure;
  analysis::JsonObject summary;  ///< summary.json: the contract's keys first, then extras
};

/// Checkpoints of a run: where they go (none by default) and, for `hypergas resume`, the
/// checkpoint to continue from, read up to the end of its header (save_header).
struct RunContext {
  Checkpointer checkpoints;
  checkpoint::Reader* resume = nullptr;
};

/// Runs the engine `o` names (options already validated); progress bar on stderr if
/// `progress` and stderr is a terminal. Throws InvalidInput for parameters the engine
/// rejects (or a checkpoint that does not fit), and InterruptedWithCheckpoint or Interrupted
/// after SIGINT/SIGTERM.
RunRecord simulate(const RunOptions& o, bool progress, RunContext& ctx);
RunRecord simulate(const RunOptions& o, bool progress);

// A checkpoint after its header (save_header) holds, in this order: the loop state, the
// conserved sums at t = 0, the recorders, the engine. start_engine reads that order and
// save_run writes it, for both engines.

/// Constructs `e` from cfg and sets c0 to its conserved sums; or, resuming (ctx.resume),
/// restores st, c0, the recorders and the engine from the checkpoint. Returns the engine.
template <class Engine, class... Recorders>
Engine& start_engine(std::optional<Engine>& e, const typename Engine::Config& cfg,
                     RunContext& ctx, DriverState& st, Conserved<Engine::dim>& c0,
                     Recorders&... rec) {
  if (ctx.resume) {
    (*ctx.resume)(st, c0, rec...);
    e.emplace(cfg, *ctx.resume);
    ctx.resume->finish();
    ++st.resumes;
  } else {
    e.emplace(cfg);
    c0 = conserved(e->particles());
  }
  return *e;
}

/// Writes a checkpoint of the run (options, loop state, c0, recorders, engine).
template <class Engine, class... Recorders>
void save_run(checkpoint::Writer& w, const RunOptions& o, const DriverState& st,
              const Conserved<Engine::dim>& c0, const Engine& e, const Recorders&... rec) {
  save_header(w, o);
  w(st, c0, rec..., e);
}

/// DSMC (time in equilibrium mean collision times).
RunRecord simulate_dsmc(const RunOptions& o, bool progress, RunContext& ctx);

/// EDMD (sigma = m = kT = 1). The first fifth of [0, until] equilibrates
/// the lattice start without sampling; moments, VACF, Z and rates come from the rest.
RunRecord simulate_edmd(const RunOptions& o, bool progress, RunContext& ctx);

/// The value of `key` in `o` as text (doubles with 4 significant digits); "-" if absent.
std::string summary_field(const analysis::JsonObject& o, const std::string& key);
/// The value of `key` in `o` as a double (NaN if absent or not a number).
double summary_number(const analysis::JsonObject& o, const std::string& key);

}  // namespace hypergas::cli
