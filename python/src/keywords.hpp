// python/src/keywords.hpp -- the keyword arguments of hypergas.DSMC / hypergas.EDMD: the
// option table's `engine` entries for each engine (hypergas/options/table.hpp), set through
// the table's typed setters, and the table and the sampling schedule as Python sees them.
#pragma once

#include <functional>

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "hypergas/options/table.hpp"
#include "hypergas/registry.hpp"

namespace hypergas::python {

namespace py = pybind11;

/// The Python names of the table's constructor options for engine `kind`; with
/// `given_velocities`, less dim, n and the options that describe an initial state.
std::vector<std::string> engine_keywords(registry::EngineKind kind, bool given_velocities);

/// The keyword arguments as validated run options of engine `kind`: defaults(kind), then
/// each keyword through the table (a value of the wrong type raises TypeError, a bad value
/// ValueError with the command's message in Python spelling), then options::validate.
/// Keywords not in `allowed` raise TypeError (as Python does); None means "not given".
/// `adjust` runs after the keywords, before validation (the command's --init-file).
options::RunOptions run_options(registry::EngineKind kind, const py::kwargs& kw,
                                const std::vector<std::string>& allowed,
                                const std::function<void(options::RunOptions&)>& adjust = {});

/// Binds option_table(), check_option(engine, name, value), given_velocity_keywords() and
/// the class Schedule (hypergas/schedule.hpp).
void bind_options(py::module_& m);

}  // namespace hypergas::python
