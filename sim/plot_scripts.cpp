// sim/plot_scripts.cpp -- the command's gnuplot scripts: variables, then the script file.
#include "plot_scripts.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "plot_run_gp.hpp"    // generated from scripts/plot_run.gp
#include "plot_scene_gp.hpp"  // generated from scripts/plot_scene.gp

namespace hypergas::cli {

std::string run_plot_script(bool vacf, int transport, bool structure) {
  return fmt::format("vacf = {}\ntransport = {}\nstructure = {}\n", vacf ? 1 : 0, transport,
                     structure ? 1 : 0) +
         std::string(embedded::plot_run_gp);
}

std::string scene_plot_script(const std::vector<int>& dims, double threshold) {
  return fmt::format("dims = \"{}\"\nthreshold = {}\n", fmt::join(dims, " "), threshold) +
         std::string(embedded::plot_scene_gp);
}

}  // namespace hypergas::cli
