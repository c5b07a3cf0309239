// sim/outputs/output.hpp -- what a run produces, one Output per kind of result.
//
// An output owns an analysis recorder (or several) and says everything the command needs
// to know about it: the observers it attaches and at which stops (the sampling stops of
// --every, or the fine grid its own physics needs), whether a checkpoint can hold it (and
// how), what it does after the last stop, the files it writes, its summary keys, its lines
// of the text summary and its gnuplot piece (scripts/run/<name>.gp). The engine runs
// (run_dsmc.hpp, run_edmd.hpp), `hypergas run`, `resume`, the sweep and the default scene
// iterate over the outputs a run asked for; none of them names an output.
//
// Adding an output with its own file: a file here defining the class and its OutputKind,
// one line in list.cpp, and (if it plots) scripts/run/<name>.gp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "../options.hpp"
#include "../run_driver.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/checkpoint.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/registry.hpp"

namespace hypergas::cli {

class OutputDir;

/// What an output knows of the run when it is made (before the engine starts).
struct RunSetup {
  const RunOptions& options;
  registry::EngineKind engine;
  RunPlan& plan;              ///< an output may set the fine grid (RunPlan::substeps)
  double window_start = 0.0;  ///< start of the measurement window (EDMD: end of equilibration)
};

/// One kind of result of a run (see the file comment).
class Output {
 public:
  virtual ~Output() = default;

  /// Observer called at every sampling stop (nullptr: none).
  virtual Observer* sampler() { return nullptr; }
  /// Observer called at every stop of the fine grid (nullptr: none).
  virtual Observer* fine() { return nullptr; }

  /// The state a checkpoint holds (OutputKind::checkpointable), in the order of the list.
  virtual void save(checkpoint::Writer&) const {}
  virtual void load(checkpoint::Reader&) {}

  /// After the last stop (correlations finished, fits made); timed as analysis.
  virtual void finish() {}
  /// Writes the files into the staging folder of `out`.
  virtual void write(OutputDir& out) const = 0;
  /// Appends the summary keys.
  virtual void summarize(analysis::JsonObject&) const {}
  /// Appends lines of the text summary `hypergas run` prints (`summary`: the run's keys).
  virtual void report(std::string& /*text*/, const analysis::JsonObject& /*summary*/) const {}
  /// The gnuplot piece (the text of scripts/run/<name>.gp), or empty: no plot.
  virtual std::string_view plot() const { return {}; }
};

/// A kind of output: when a run has it, and how it is made.
struct OutputKind {
  std::string_view name;
  bool (*wanted)(const RunOptions&, registry::EngineKind);
  std::unique_ptr<Output> (*make)(const RunSetup&);
  /// Whether a checkpoint can hold the output's state (save, load); a run is checkpointed
  /// only when every output it has can be.
  bool checkpointable = true;
};

/// An output that takes every m-th sampling instant from the first, about `interval` apart:
/// m = max(1, round(interval / sampling interval)) (--histogram-every, --trajectory-every).
inline std::uint64_t sampling_stride(const RunPlan& plan, double interval) {
  return static_cast<std::uint64_t>(std::max(1.0, std::round(interval / plan.sampling.every())));
}

/// OutputKind::make of an output class T constructed from the RunSetup.
template <class T>
std::unique_ptr<Output> make_output(const RunSetup& s) {
  return std::make_unique<T>(s);
}

/// The outputs a run asked for, in the order of the list (list.cpp): the order of their
/// checkpoint sections, files, summary keys, text lines and plots.
std::vector<std::unique_ptr<Output>> make_outputs(const RunSetup& setup);

/// The gnuplot script of a run folder (written as plot.gp beside the PNGs): the run's
/// variables from its summary (run_title "dsmc, D = 3, N = 1000, hs, seed 1"; granular and,
/// for a cooling gas, time_unit, haff_from, haff_t0, a2_sonine), scripts/plot_run.gp and
/// each output's piece.
std::string plot_script(const std::vector<std::unique_ptr<Output>>& outputs,
                        const analysis::JsonObject& summary);

/// Whether a run with options `o` can be checkpointed: one system (no replicas), and a
/// checkpoint can hold every output it has.
bool checkpointable(const RunOptions& o);

}  // namespace hypergas::cli
