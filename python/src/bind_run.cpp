// python/src/bind_run.cpp -- `hypergas run` from Python: run_command(out, engine, **kw) builds
// the run's options from the keywords through the option table (every run option of the
// engine, Python spelling, checked as the command checks them) and calls the command's
// own run (sim/run_command.cpp), so the same engine runs and the same outputs
// (sim/outputs/) write the same files into `out`. hypergas.run (hypergas/_run.py) wraps it
// and returns summary.json.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "bindings.hpp"
#include "commands.hpp"
#include "init_file.hpp"
#include "hypergas/options/table.hpp"
#include "hypergas/registry.hpp"
#include "keywords.hpp"

namespace hypergas::python {

namespace {

/// The keywords of a run of engine `kind`: every option of the table that applies to it,
/// less those run() takes itself (engine, out) and the command's --json.
std::vector<std::string> run_keywords(registry::EngineKind kind) {
  std::vector<std::string> k;
  for (const options::Option& opt : options::run_table())
    if (options::applies(opt, kind) && opt.name != "engine" && opt.name != "out" &&
        opt.name != "json")
      k.push_back(options::python_name(opt));
  return k;
}

}  // namespace

void bind_run(py::module_& m) {
  m.def(
      "run_keywords",
      [](const std::string& engine) { return run_keywords(registry::engine(engine)); },
      py::arg("engine"), "The keyword arguments hypergas.run takes for `engine`.");
  m.def(
      "run_command",
      [](const std::string& out, const std::string& engine, const py::kwargs& kw) {
        const registry::EngineKind kind = registry::engine(engine);
        // --init-file sets D and N (EDMD: the packing) from its file, as the command does
        options::RunOptions o = run_options(kind, kw, run_keywords(kind), cli::apply_init_file);
        o.out = out;
        py::gil_scoped_release unlocked;  // the run touches no Python object
        return cli::run_command(o, nullptr, true);
      },
      py::arg("out"), py::arg("engine") = "dsmc",
      "`hypergas run --engine ENGINE --out OUT` with the keywords as its options; returns "
      "the exit code (0).");
}

}  // namespace hypergas::python
