// python/src/module.cpp -- the extension module `hypergas._hypergas`: the engines, the
// analysis recorders and the studies, bound with pybind11. The Python package
// (python/hypergas/__init__.py) builds the public API on top of it.
//
// Conventions of the bindings:
//  - Options are the command's option table (hypergas/options/table.hpp), set and
//    validated by the same code as the command's (keywords.hpp), so a bad value gets the command's message with the Python spelling of the option
//    ("--mass-ratio" becomes "mass_ratio"); InvalidInput becomes ValueError, a value of
//    the wrong type TypeError (convert.hpp, keywords.hpp).
//  - Per-particle arrays are numpy views of the engine's memory (no copy), read-only, and
//    keep the engine alive (arrays.hpp). Engine calls that could move or change that
//    memory while a run is in progress on another Python thread raise RuntimeError instead.
//  - advance() releases the GIL; every ~0.1 s of wall time it takes the GIL back to let
//    Python handle signals (Ctrl-C raises KeyboardInterrupt with the engine consistent at
//    the time reached) and to call the progress function (bind_engines.cpp).
#include <pybind11/pybind11.h>

#include <exception>
#include <string>

#include "bindings.hpp"
#include "keywords.hpp"
#include "convert.hpp"
#include "hypergas/error.hpp"
#include "version.hpp"

PYBIND11_MODULE(_hypergas, m) {
  using namespace hypergas;
  using namespace hypergas::python;
  m.doc() = "hypergas engines and analysis (compiled part; use the `hypergas` package)";

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      PyErr_SetString(PyExc_ValueError, python_spelling(e.what()).c_str());
    }
  });

  bind_analysis(m);
  bind_observers(m);
  bind_engines(m);
  bind_report(m);
  bind_options(m);
  bind_run(m);
  // the project version, that of `hypergas --version` and summary.json's "version"
  m.attr("version") = std::string(cli::version());
}
