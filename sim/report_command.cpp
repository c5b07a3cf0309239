// sim/report_command.cpp -- `hypergas report`: error against run time (CSV + PNG).
//
// A hook: the subcommand is registered so that `hypergas report --help` and the option
// structure exist; the study itself is still to be written (see DESIGN.md section 5).
#include <fmt/core.h>

#include "commands.hpp"

namespace hypergas::cli {

CLI::App* add_report_command(CLI::App& app) {
  return app.add_subcommand("report", "error against run time: CSV + PNG (not implemented yet)");
}

int report_command() {
  fmt::print(stderr, "hypergas report: not implemented yet\n");
  return 1;
}

}  // namespace hypergas::cli
