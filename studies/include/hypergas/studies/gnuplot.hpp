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

/// True when a `gnuplot` executable is on PATH.
bool gnuplot_available();

/// The work-precision figure script, scripts/plot_report.gp (`hypergas report`).
std::string_view report_plot_script();

}  // namespace hypergas::studies
