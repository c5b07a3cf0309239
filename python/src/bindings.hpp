// python/src/bindings.hpp -- the parts of the extension module `hypergas._hypergas`, one
// function per area, called in this order by PYBIND11_MODULE (module.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace hypergas::python {

/// The registry's names, jamming_packing, maxwell_pdf/cdf, vacf and msd (bind_analysis.cpp).
void bind_analysis(pybind11::module_& m);
/// Observer, MomentsRecorder and VacfRecorder (bind_observers.cpp).
void bind_observers(pybind11::module_& m);
/// The Engine class and its factories and per-engine functions (bind_engines.cpp); after
/// bind_observers, whose Observer type Engine.observe takes.
void bind_engines(pybind11::module_& m);
/// The error-against-run-time study (bind_report.cpp).
void bind_report(pybind11::module_& m);
/// run_command and run_keywords: `hypergas run` from Python (bind_run.cpp).
void bind_run(pybind11::module_& m);

}  // namespace hypergas::python
