// sim/progress.hpp -- a progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <chrono>
#include <string>

namespace hypergas::cli {

/// Shows `label [#####.....]  42%  t = 4.2 of 10  eta 3 s` (the engine's time and the end
/// time, and the wall time left at the rate so far) on one stderr line, redrawn at most ten times
/// a second; does nothing at all when stderr is not a terminal (pipes, files, tests).
class Progress {
 public:
  /// `total` is the amount of work in any unit (e.g. the end time of the run).
  Progress(std::string label, double total);
  ~Progress();
  /// Reports that `done` of `total` is finished.
  void update(double done);
  /// Clears the bar (also done by the destructor).
  void finish();
  /// True when stderr is a terminal (the bar is drawn).
  static bool enabled();

 private:
  std::string label_;
  double total_;
  bool on_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

/// While it lives, one stderr line saying what a run is setting up before its first
/// collision (`label: setting up ...`: the lattice start and its compression, the initial
/// velocities), which can take as long as the run; cleared when done. Only on a terminal,
/// as the bar; the time it took is the summary's setup_s.
class SetupLine {
 public:
  SetupLine(const std::string& text, bool show);
  ~SetupLine();
  SetupLine(const SetupLine&) = delete;
  SetupLine& operator=(const SetupLine&) = delete;

 private:
  bool on_;
};

/// Set by SIGINT/SIGTERM once `install_interrupt_handler` ran; long loops poll it and
/// throw Interrupted so that output folders are cleaned up.
bool interrupted();
/// Installs the SIGINT/SIGTERM handler that sets the `interrupted()` flag (once: a second
/// signal terminates the process immediately).
void install_interrupt_handler();

/// Thrown by a run loop that saw `interrupted()`; main() exits with 130.
struct Interrupted {};

}  // namespace hypergas::cli
