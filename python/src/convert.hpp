// python/src/convert.hpp -- Python values as C++ arguments: integers, seeds, reals and
// strings with the module's TypeError/ValueError rules, and the Python spelling of messages.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

namespace hypergas::python {

namespace py = pybind11;

/// "--mass-ratio must be ..." -> "mass_ratio must be ...": the command's messages in the
/// spelling of the Python keyword arguments.
std::string python_spelling(const std::string& msg);

/// Raises TypeError with `msg`.
[[noreturn]] void type_error(const std::string& msg);

/// The name of h's Python type ("str", "float", ...).
std::string type_name(const py::handle& h);

/// An integer argument: Python ints, numpy integers, and floats with an integral value
/// (1e6); bool is refused.
long long as_integer(const std::string& name, const py::handle& h);

/// A seed: an integer in 0..2^64-1 (bool refused).
std::uint64_t as_seed(const py::handle& h);

/// A real argument: int, float or numpy scalar; strings and bools are refused.
double as_real(const std::string& name, const py::handle& h);

/// A string argument (str only).
std::string as_text(const std::string& name, const py::handle& h);

}  // namespace hypergas::python
