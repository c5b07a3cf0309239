// hypergas/studies/gnuplot.hpp -- PNG plots through gnuplot, run as a subprocess.
//
// The scripts are files of the repository (scripts/*.gp), compiled into the programs at
// build time (cmake/HypergasEmbed.cmake); a caller prepends the variables a script reads.
#pragma once

#include <filesystem>
#include <string_view>

namespace hypergas::studies {

/// Runs `gnuplot` on `script` (fed on its stdin) with working folder `dir`, so the script
/// names CSV and PNG files relative to it. If gnuplot is not installed, prints one warning
/// on stderr (once per process) and returns false (the caller's CSV files stand); also false
/// if gnuplot fails (its messages go to stderr).
bool run_gnuplot(std::string_view script, const std::filesystem::path& dir);

/// A gnuplot process started ahead of its script: the program's start (most of a plot's
/// wall time, 0.03-0.1 s) then overlaps the caller's work, and finish() only feeds the
/// script and waits. Without gnuplot on PATH it does nothing and finish() warns as
/// run_gnuplot does. Destroyed unfinished (an exception, Ctrl-C), it kills the process and
/// reaps it: nothing is plotted.
class GnuplotProcess {
 public:
  explicit GnuplotProcess(const std::filesystem::path& dir);
  ~GnuplotProcess();
  GnuplotProcess(const GnuplotProcess&) = delete;
  GnuplotProcess& operator=(const GnuplotProcess&) = delete;
  /// Feeds `script` to gnuplot and waits for it; as run_gnuplot's return value.
  bool finish(std::string_view script);

 private:
  int pid_ = -1;
  int fd_ = -1;
};

/// True when a `gnuplot` executable is on PATH.
bool gnuplot_available();

/// The work-precision figure script, scripts/plot_report.gp (`hypergas report`).
std::string_view report_plot_script();

}  // namespace hypergas::studies
