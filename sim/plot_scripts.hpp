// sim/plot_scripts.hpp -- the gnuplot scripts of the command's PNG plots: the files
// scripts/plot_run.gp and scripts/plot_scene.gp (compiled in at build time), preceded by
// the variables they read. Run them with studies::run_gnuplot (hypergas/studies/gnuplot.hpp).
#pragma once

#include <string>
#include <vector>

namespace hypergas::cli {

/// Plots of one `hypergas run` folder: moments.png (kurtosis and L1 distance against
/// time), speed_histogram.png (final speeds against MB), with `vacf` vacf.png and with
/// `transport` transport.png (1, DSMC: the normalised correlations beside their first
/// Sonine exponentials; 2, EDMD: the correlations and the running Einstein-Helfand
/// values), with `structure` structure.png (g(r) and S(k)).
std::string run_plot_script(bool vacf, int transport = 0, bool structure = false);

/// Plots of the default scene: relaxation.png (L1 distance from MB against collisions per
/// particle, every D), kurtosis.png and speed_histograms.png (final state, one panel per D).
/// `dims` lists the dimensions with files relaxation_D<d>.csv and speed_histogram_D<d>.csv;
/// `threshold` is the stated L1 distance drawn as a line.
std::string scene_plot_script(const std::vector<int>& dims, double threshold);

}  // namespace hypergas::cli
