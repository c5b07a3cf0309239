// hypergas/error.hpp -- the exception types the core throws on bad input.
#pragma once

#include <stdexcept>

namespace hypergas {

/// Bad input to a library function (bad normal, bad mass, bad state). The message names
/// the argument and the value; the CLI turns it into a message on stderr and exit code 2.
class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace hypergas
