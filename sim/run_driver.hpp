// sim/run_driver.hpp -- the loop of `hypergas run` and `hypergas resume`: moves an engine from
// stop to stop, observes at the sampling stops, writes checkpoints and honours Ctrl-C.
//
// A run is a fixed sequence of stops, a pure function of the options (RunPlan::stop(k)):
//   DSMC  the sampling instants of hypergas::Schedule from 0 to `until` (the rule of both
//         engines' run_until and of Python's run: evenly spaced, the last at `until`).
//   EDMD  ten equilibration stops at t_eq (k + 1) / 10 without sampling, the last of which
//         (t_eq) starts the measurement window and takes the first sample; then the
//         Schedule's instants from t_eq to `until`.
// Between two sampling instants an output may ask for a finer grid (RunPlan::substeps: the
// correlations of DSMC --transport, the EDMD VACF), whose stops observe its fine observers
// only; every sampling instant is also a stop of the fine grid.
// Stopping an engine at a time and going on does not change its trajectory where the plan
// puts the stops: DSMC stops only at its sampling grid (an epoch of the exact scheme ends at
// each grid point in any case); EDMD processes the same events in the same order whatever
// times run_until is given. A checkpoint is written only just after a stop, with the index
// of the next stop, so a resumed run makes the same calls on the same state as one that
// never stopped, and its files are the same bit for bit.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "hypergas/checkpoint.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/schedule.hpp"
#include "options.hpp"
#include "progress.hpp"

namespace hypergas::cli {

/// One stop of a run: advance to `time`; then start the measurement window (EDMD) and/or
/// observe.
struct Stop {
  double time = 0.0;
  bool start_window = false;
  bool sample = false;
  bool fine = false;  ///< a stop of the fine grid (RunPlan::substeps)
};

/// The stops of a run (see the file comment).
struct RunPlan {
  Schedule sampling;         ///< the sampled instants, sampling.t0() .. sampling.until()
  int warmup_stops = 0;      ///< EDMD: equilibration stops (the last one samples), DSMC: 0
  /// Fine stops per sampling interval (evenly spaced; the first is the sampling instant),
  /// set by the outputs that sample faster than --every (DSMC --transport, the EDMD
  /// VACF). 1: the sampling instants only.
  std::uint64_t substeps = 1;
  /// EDMD granular run: the restitution the engine gets after each sample (the first at
  /// the end of the equilibration, which runs elastic): the cooling starts from the
  /// equilibrium fluid. Unset: the engine's own.
  std::optional<double> quench;

  /// Stop k, or nothing after the last one.
  std::optional<Stop> stop(std::uint64_t k) const;
};

/// What the loop has done so far; saved in a checkpoint.
struct DriverState {
  std::uint64_t next_stop = 0;     ///< index of the next stop to make
  double last_checkpoint = 0.0;    ///< engine time of the last checkpoint written
  double engine_s = 0.0;           ///< wall seconds in the engine, all processes together
  double analysis_s = 0.0;         ///< wall seconds in the recorders, all processes together
  std::uint64_t checkpoints = 0;   ///< checkpoints written, all processes together
  std::uint64_t resumes = 0;       ///< times this run was resumed

  template <class Archive>
  void io(Archive& a) {
    a.tag("driver");
    a(next_stop, last_checkpoint, engine_s, analysis_s, checkpoints, resumes);
  }
};

/// When to write checkpoints, and where.
class Checkpointer {
 public:
  /// No checkpoints at all (the default scene, replicas).
  Checkpointer() = default;
  /// Checkpoints into `dir`/checkpoint.hgck every `every` time units of the engine and/or
  /// every `wall_s` seconds of wall time (0 = not by that rule), and on Ctrl-C.
  Checkpointer(std::filesystem::path dir, double every, double wall_s);

  bool enabled() const { return !dir_.empty(); }
  /// Whether a checkpoint is due after a stop at engine time t.
  bool due(double t, const DriverState& st) const;
  /// Writes a checkpoint: `save(writer)` writes the contents; then the file is committed.
  template <class Save>
  void write(Save&& save) {
    checkpoint::Writer w(path().string());
    save(w);
    w.commit();
    last_wall_ = std::chrono::steady_clock::now();
  }
  std::filesystem::path path() const { return dir_ / file_name; }
  const std::filesystem::path& dir() const { return dir_; }

  /// Also writes the state at the end of the run to `file` (a finished run that
  /// `hypergas resume DIR --until T` can continue); empty: not.
  void keep_final(std::filesystem::path file) { final_ = std::move(file); }
  /// Writes the final state, if kept (keep_final).
  template <class Save>
  void write_final(Save&& save) const {
    if (final_.empty()) return;
    checkpoint::Writer w(final_.string());
    save(w);
    w.commit();
  }

  static constexpr const char* file_name = "checkpoint.hgck";
  /// The state a finished run keeps when it was checkpointed (run_command.cpp).
  static constexpr const char* final_name = "final.hgck";

 private:
  std::filesystem::path dir_, final_;
  double every_ = 0.0, wall_s_ = 0.0;
  std::chrono::steady_clock::time_point last_wall_ = std::chrono::steady_clock::now();
};

/// Thrown after Ctrl-C once a checkpoint is written (main() prints how to resume).
struct InterruptedWithCheckpoint {
  std::filesystem::path dir;
  double time = 0.0;
};

/// Runs `engine` through the stops of `plan` from st.next_stop on, observing with `obs`;
/// after each stop writes a checkpoint through ck when due (save(writer) writes it, with
/// `st` already updated). Ends with the engine at plan.until. Throws
/// InterruptedWithCheckpoint (checkpointing on) or Interrupted (off) after SIGINT/SIGTERM.
/// `fine`, if set, observes at every stop of the fine grid (RunPlan::substeps). At the end
/// writes the final state through ck when it keeps it (Checkpointer::keep_final).
template <class Engine, class Save>
void drive(Engine& engine, const RunPlan& plan, DriverState& st, Observer& obs,
           Checkpointer& ck, Save&& save, Observer* fine = nullptr) {
  using Clock = std::chrono::steady_clock;
  for (;;) {
    const std::optional<Stop> s = plan.stop(st.next_stop);
    if (!s) break;
    const auto t0 = Clock::now();
    engine.run_until(s->time);
    if constexpr (requires { engine.reset_observables(); })
      if (s->start_window) engine.reset_observables();
    const auto t1 = Clock::now();
    if (s->fine && fine) engine.observe(*fine);
    if (s->sample) engine.observe(obs);
    if constexpr (requires { engine.set_restitution(1.0); })
      if (s->sample && plan.quench && engine.restitution() != *plan.quench)
        engine.set_restitution(*plan.quench);
    const auto t2 = Clock::now();
    st.engine_s += std::chrono::duration<double>(t1 - t0).count();
    st.analysis_s += std::chrono::duration<double>(t2 - t1).count();
    ++st.next_stop;
    const bool stop_now = interrupted();
    if (ck.enabled() && (stop_now || ck.due(engine.time(), st))) {
      st.last_checkpoint = engine.time();
      ++st.checkpoints;
      ck.write(save);
    }
    if (stop_now) {
      if (ck.enabled()) throw InterruptedWithCheckpoint{ck.dir(), engine.time()};
      throw Interrupted{};
    }
  }
  const auto t0 = Clock::now();
  engine.run_until(plan.sampling.until());
  st.engine_s += std::chrono::duration<double>(Clock::now() - t0).count();
  ck.write_final(save);
}

/// "hypergas <version> (<compiler>)": a checkpoint is continued only by the same build.
std::string build_identity();

/// Writes the run's header: section "hypergas-run", build_identity(), the options that
/// resume parses again (options::replay_arguments), then the --init-file frame the run
/// started from (RunOptions::init_frame_read, init_checksum; -1 and "" without one).
void save_header(checkpoint::Writer& w, const RunOptions& o);

/// Peak resident memory of this process so far (bytes; getrusage).
double peak_rss_bytes();

}  // namespace hypergas::cli
