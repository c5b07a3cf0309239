// sim/plot_scripts.hpp -- the gnuplot script of the default scene's PNG plots: the file
// scripts/plot_scene.gp (compiled in at build time), preceded by the variables it reads (a
// run folder's script is its outputs': outputs/output.hpp). Run them with studies::run_gnuplot (hypergas/studies/gnuplot.hpp).
#pragma once

#include <string>
#include <vector>

namespace hypergas::cli {

/// Plots of the default scene: relaxation.png (L1 distance from MB against collisions per
/// particle, every D), kurtosis.png and speed_histograms.png (final state, one panel per D).
/// `dims` lists the dimensions with files relaxation_D<d>.csv and speed_histogram_D<d>.csv;
/// `threshold` is the stated L1 distance drawn as a line.
std::string scene_plot_script(const std::vector<int>& dims, double threshold);

}  // namespace hypergas::cli
