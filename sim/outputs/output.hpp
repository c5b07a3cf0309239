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
// An output's OutputKind declares what the rest of the program needs to know before it is
// made: when a run has it, the files it writes (and the one it writes as the run goes, which
// the folder code leaves alone), the fine grid it samples on (the run's grid is the finest
// any wanted output asks for, computed once before any output is made), and the outputs it
// replaces. Its summary keys are its own: no run body and no other output writes them
// (summarize_outputs refuses a key written twice).
//
// Adding an output with its own file: a file here defining the class and its OutputKind,
// one line in list.cpp, and (if it plots) scripts/run/<name>.gp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
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
class MomentsOutput;

/// What an output knows of the run when it is made (before the engine starts).
struct RunSetup {
  const RunOptions& options;
  registry::EngineKind engine;
  const RunPlan& plan;        ///< the stops, fine grid included (plan_substeps)
  double window_start = 0.0;  ///< start of the measurement window (EDMD: end of equilibration)
  /// The moments output, which every run has first; set by make_outputs for the outputs
  /// after it (the granular keys read its rows).
  const MomentsOutput* moments = nullptr;
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
  /// The files it may write into the run folder (through the staging folder, at the end);
  /// its PNGs are those its plot draws where gnuplot is found.
  std::span<const std::string_view> files = {};
  /// The file it writes in the run folder itself as the run goes (the commit moves it to
  /// its name among `files`), or empty.
  std::string_view partial = {};
  /// The fine stops per sampling interval it needs (RunPlan::substeps), from the options
  /// and the sampling instants; nullptr: none (1).
  std::uint64_t (*substeps)(const RunOptions&, const Schedule& sampling) = nullptr;
  /// The outputs (by name) that a run with this one does not have: it writes their keys
  /// its own way.
  std::span<const std::string_view> excludes = {};
};

/// The fine stops per sampling interval of a run (RunPlan::substeps): the most that any of
/// its outputs asks for, 1 if none does.
std::uint64_t plan_substeps(const RunOptions& o, registry::EngineKind engine,
                            const Schedule& sampling);

/// Whether `name` is a file that an output writes in a run folder as the run goes
/// (OutputKind::partial).
bool partial_output_file(std::string_view name);

/// Throws std::logic_error if `names` (the files of a run's staging folder) hold one that
/// no output of a run with options `o` declares (OutputKind::files), other than the run's
/// own summary.json, plot.gp and final state (Checkpointer::final_name).
void check_declared_files(const std::vector<std::string>& names, const RunOptions& o);

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
