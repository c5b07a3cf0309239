// sim/run_observer.hpp -- the observer a command hands to an engine: forwards each snapshot
// to the analysis recorders, draws the progress bar, and measures the wall time spent in
// analysis.
#pragma once

#include <cstddef>
#include <vector>

#include "hypergas/observer.hpp"
#include "hypergas/particles.hpp"
#include "progress.hpp"

namespace hypergas::cli {

/// Forwards snapshots to `targets`, updates a progress bar over [0, end_time], and measures
/// the wall time spent in the targets. (Ctrl-C is handled between stops: run_driver.hpp.)
class RunObserver final : public Observer {
 public:
  RunObserver(std::vector<Observer*> targets, const char* label, double end_time,
              bool show_progress = true);
  void observe(const Snapshot& s) override;
  void request(tally::Requests& r) override;

  std::size_t snapshots() const { return count_; }
  /// Wall seconds spent in the targets (analysis), to subtract from the engine's time.
  double analysis_seconds() const { return analysis_s_; }

 private:
  std::vector<Observer*> targets_;
  Progress progress_;
  bool show_;
  std::size_t count_ = 0;
  double analysis_s_ = 0.0;
};

}  // namespace hypergas::cli
