// python/src/keywords.hpp -- the keyword arguments of hypergas.DSMC / hypergas.EDMD and
// their translation into the command's run options.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "hypergas/registry.hpp"
#include "options.hpp"

namespace hypergas::python {

namespace py = pybind11;

/// The keywords hypergas.DSMC and hypergas.EDMD accept (run_options' `allowed`).
extern const std::vector<std::string> dsmc_keywords;
extern const std::vector<std::string> edmd_keywords;

/// The keyword arguments of hypergas.DSMC / hypergas.EDMD as the command's run options,
/// validated by cli::validate. Keywords not in `allowed` raise TypeError (as Python does).
cli::RunOptions run_options(registry::EngineKind kind, const py::kwargs& kw,
                            const std::vector<std::string>& allowed);

}  // namespace hypergas::python
