// sim/version.hpp -- what build of hypergas this is: `hypergas --version`, and the
// `version` and `git` keys of every summary.json (so of sweep.csv too).
#pragma once

#include <string>
#include <string_view>

namespace hypergas::cli {

/// The project version (CMakeLists.txt, project()).
std::string_view version();
/// `git describe --always --dirty --tags` of the source tree when the command was built, or
/// "unknown" outside a git checkout (generated at build time: cmake/GitDescribe.cmake).
std::string_view git_describe();
/// "hypergas <version> (git <describe>)".
std::string version_line();

}  // namespace hypergas::cli
