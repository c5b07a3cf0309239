// python/src/bind_report.cpp -- `report`: the error-against-run-time study
// (studies/report.hpp) run from Python, its results as dicts and lists.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <utility>

#include "bindings.hpp"
#include "convert.hpp"
#include "hypergas/error.hpp"
#include "hypergas/options/run_options.hpp"
#include "hypergas/studies/report.hpp"

namespace hypergas::python {

void bind_report(py::module_& m) {
  m.def("report", [](bool quick, const py::object& seed, const py::object& threads) {
    studies::ReportOptions o;
    o.quick = quick;
    o.seed = as_seed(seed);
    const long long t = as_integer("threads", threads);
    options::check_threads(t, "threads");
    o.threads = static_cast<int>(t);
    o.plot = false;
    o.verbose = false;
    studies::ReportResult r;
    {
      py::gil_scoped_release nogil;
      r = studies::run_report_study(o);
    }
    py::list points, slopes, finite_n, ntc;
    for (const auto& p : r.points)
      points.append(py::dict(py::arg("study") = p.study, py::arg("engine") = p.engine,
                             py::arg("dim") = p.dim, py::arg("param") = p.param,
                             py::arg("run_s") = p.run_s, py::arg("error") = p.error,
                             py::arg("error_se") = p.error_se, py::arg("replicas") = p.replicas));
    for (const auto& s : r.slopes)
      slopes.append(py::dict(py::arg("study") = s.study, py::arg("engine") = s.engine,
                             py::arg("dim") = s.dim, py::arg("slope") = s.slope,
                             py::arg("slope_se") = s.slope_se, py::arg("points") = s.points));
    for (auto [list, rows] : {std::pair{&finite_n, &r.finite_n}, std::pair{&ntc, &r.ntc}})
      for (const auto& b : *rows)
        list->append(py::dict(py::arg("dim") = b.dim, py::arg("param") = b.param,
                              py::arg("bias") = b.bias, py::arg("bias_se") = b.bias_se,
                              py::arg("theory") = b.theory));
    py::dict d;
    d["points"] = points, d["slopes"] = slopes, d["finite_n"] = finite_n, d["ntc"] = ntc;
    d["ntc_order"] = r.ntc_order, d["ntc_order_se"] = r.ntc_order_se, d["total_s"] = r.total_s;
    return d;
  }, py::arg("quick") = true, py::arg("seed") = 1, py::arg("threads") = 2);
}

}  // namespace hypergas::python
