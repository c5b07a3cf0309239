// sim/version.cpp -- the version line (version.hpp); git_describe() is generated.
#include "version.hpp"

#ifndef HYPERGAS_VERSION
#define HYPERGAS_VERSION "unknown"
#endif

namespace hypergas::cli {

std::string_view version() { return HYPERGAS_VERSION; }

std::string version_line() {
  return "hypergas " + std::string(version()) + " (git " + std::string(git_describe()) + ")";
}

}  // namespace hypergas::cli
