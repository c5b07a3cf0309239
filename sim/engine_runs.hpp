// sim/engine_runs.hpp -- one run of an engine, as `hypergas run`, `resume`, the sweep and the
// default scene use it.
//
// `simulate` reaches the engine the options name through registry::with_engine
// (hypergas/engines.hpp), runs it with the run's outputs attached (outputs/output.hpp) and
// returns the outputs, finished, and the summary; the callers write the files. The engine
// runs are compiled once per dimension: run_dim.cpp.in, generated for each D of the one
// instantiation list (cmake/HypergasDims.cmake).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "hypergas/analysis/output.hpp"
#include "hypergas/conserved.hpp"
#include "init_file.hpp"
#include "options.hpp"
#include "outputs/moments.hpp"
#include "outputs/output.hpp"
#include "run_driver.hpp"

namespace hypergas::cli {

/// What one engine run produced.
struct RunRecord {
  std::vector<std::unique_ptr<Output>> outputs;  ///< finished, in the order of outputs/list.cpp
  analysis::JsonObject summary;  ///< summary.json: the contract's keys first, then extras
  /// The moments output (every run has it, first).
  const MomentsOutput& moments() const { return static_cast<const MomentsOutput&>(*outputs.front()); }
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
// conserved sums at t = 0, the checkpointable outputs in list order, the engine.
// start_engine reads that order and save_run writes it, for both engines.

/// Constructs `e` from cfg (or from o's --init-file) and sets c0 to its conserved sums; or,
/// resuming (ctx.resume),
/// restores st, c0, the outputs and the engine from the checkpoint. Returns the engine.
template <class Engine>
Engine& start_engine(std::optional<Engine>& e, const typename Engine::Config& cfg,
                     RunContext& ctx, DriverState& st, Conserved<Engine::dim>& c0,
                     const std::vector<std::unique_ptr<Output>>& outputs,
                     const RunOptions& o) {
  if (ctx.resume) {
    (*ctx.resume)(st, c0);
    for (const auto& out : outputs) out->load(*ctx.resume);
    e.emplace(cfg, *ctx.resume);
    ctx.resume->finish();
    ++st.resumes;
  } else {
    if (o.init_file.empty()) e.emplace(cfg);
    else emplace_from_file(e, cfg, o.init_file, o.init_frame);  // init_file.hpp
    c0 = conserved(e->particles());
  }
  return *e;
}

/// Writes a checkpoint of the run (options, loop state, c0, outputs, engine).
template <class Engine>
void save_run(checkpoint::Writer& w, const RunOptions& o, const DriverState& st,
              const Conserved<Engine::dim>& c0, const Engine& e,
              const std::vector<std::unique_ptr<Output>>& outputs) {
  save_header(w, o);
  w(st, c0);
  for (const auto& out : outputs) out->save(w);
  w(e);
}

/// Where a run's sampling starts: 0 for DSMC; for EDMD the end of the lattice start's
/// equilibration, --equilibration or a fifth of --until (run_edmd.hpp, and resume --until,
/// which keeps it).
double sampling_start(const RunOptions& o);

/// The observers of `outputs` at the sampling stops and at the fine stops.
std::vector<Observer*> samplers(const std::vector<std::unique_ptr<Output>>& outputs);
std::vector<Observer*> fine_observers(const std::vector<std::unique_ptr<Output>>& outputs);

/// Calls finish() on every output, adding the wall time to st.analysis_s.
void finish_outputs(const std::vector<std::unique_ptr<Output>>& outputs, DriverState& st);

/// The engine's own summary keys (Engine::describe), in its order.
template <class Engine>
analysis::JsonObject engine_facts(const Engine& e) {
  analysis::JsonObject keys;
  e.describe([&](std::string_view key, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_arithmetic_v<T>) keys.emplace_back(std::string(key), value);
    else keys.emplace_back(std::string(key), std::string(value));
  });
  return keys;
}

/// Appends every output's summary keys to `summary`; throws std::logic_error if a key is
/// then there twice (each has one owner).
void summarize_outputs(const std::vector<std::unique_ptr<Output>>& outputs,
                       analysis::JsonObject& summary);

namespace detail {
/// The runs of dimension D, every engine of the registry (run_dim.hpp; compiled in the
/// translation unit generated for D from run_dim.cpp.in).
template <int D>
RunRecord run_dim(const RunOptions& o, bool progress, RunContext& ctx);
}  // namespace detail

}  // namespace hypergas::cli
