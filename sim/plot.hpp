// sim/plot.hpp -- PNG plots through gnuplot, run as a subprocess with a generated script.
#pragma once

#include <filesystem>
#include <string>

namespace hypergas::cli {

/// Runs `gnuplot` on `script` with working folder `dir` (so the script names CSV and PNG
/// files relative to it). If gnuplot is not installed, prints one warning on stderr and
/// returns false (the CSV files are still written by the caller); also false if gnuplot
/// fails (its messages go to stderr).
bool run_gnuplot(const std::string& script, const std::filesystem::path& dir);

/// True when a `gnuplot` executable is on PATH.
bool gnuplot_available();

}  // namespace hypergas::cli
