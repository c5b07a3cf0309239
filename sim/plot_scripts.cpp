// sim/plot_scripts.cpp -- the default scene's gnuplot script: variables, then the file.
#include "plot_scripts.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "plot_scene_gp.hpp"  // generated from scripts/plot_scene.gp

namespace hypergas::cli {

std::string scene_plot_script(const std::vector<int>& dims, double threshold) {
  return fmt::format("dims = \"{}\"\nthreshold = {}\n", fmt::join(dims, " "), threshold) +
         std::string(embedded::plot_scene_gp);
}

}  // namespace hypergas::cli
