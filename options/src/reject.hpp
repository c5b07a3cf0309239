// options/src/reject.hpp -- how the option files refuse a value: InvalidInput with the
// message (main turns it into one stderr line and exit code 2). One definition for
// table.cpp and validate.cpp, which a unity build compiles together.
#pragma once

#include <string>

#include "hypergas/error.hpp"

namespace hypergas::options::detail {

[[noreturn]] inline void reject(const std::string& message) { throw InvalidInput(message); }

}  // namespace hypergas::options::detail
