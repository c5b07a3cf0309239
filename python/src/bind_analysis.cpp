// python/src/bind_analysis.cpp -- the registry's names and the analysis functions of the
// module: engine/model/initial-state/scheme names, jamming_packing, maxwell_pdf/cdf, vacf, msd.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/analysis/vacf.hpp"
#include "hypergas/edmd/box.hpp"
#include "hypergas/error.hpp"
#include "hypergas/registry.hpp"

namespace hypergas::python {
namespace {

analysis::Quantity quantity(const std::string& q) {
  if (q == "speed") return analysis::Quantity::speed;
  if (q == "component") return analysis::Quantity::component;
  if (q == "energy") return analysis::Quantity::energy;
  throw InvalidInput("unknown quantity '" + q + "' (known: speed, component, energy)");
}

}  // namespace

void bind_analysis(py::module_& m) {
  // ---- the registry's names (for help texts and checks on the Python side)
  m.def("engine_names", [] {
    std::vector<std::string> v;
    for (auto s : registry::engine_names()) v.emplace_back(s);
    return v;
  });
  m.def("model_names", [] {
    std::vector<std::string> v;
    for (auto s : registry::model_names()) v.emplace_back(s);
    return v;
  });
  m.def("initial_state_names", [] {
    std::vector<std::string> v;
    for (auto s : registry::initial_state_names()) v.emplace_back(s);
    return v;
  });
  m.def("jamming_packing", [](int dim) {
    if (dim < min_dim || dim > max_dim) throw InvalidInput("dim must be in 1..6, got " + std::to_string(dim));
    return edmd::jamming_packing(dim);
  }, py::arg("dim"), "The largest EDMD packing accepted in dimension dim (its jamming density).");
  m.def("scheme_names", [] {
    std::vector<std::string> v;
    for (auto s : registry::scheme_names()) v.emplace_back(s);
    return v;
  });

  // ---- analysis functions
  // MB density and distribution: the same arguments, the member function differs.
  const auto maxwell = [](double (analysis::MaxwellReference::*f)(double) const) {
    return [f](const py::handle& x, int dim, double kT, double mass, const std::string& q) {
      const analysis::MaxwellReference ref{quantity(q), dim, kT, mass};
      ref.validate();
      return elementwise(x, [&](double v) { return (ref.*f)(v); });
    };
  };
  for (auto [name, f] : {std::pair{"maxwell_pdf", &analysis::MaxwellReference::pdf},
                         std::pair{"maxwell_cdf", &analysis::MaxwellReference::cdf}})
    m.def(name, maxwell(f), py::arg("x"), py::arg("dim"), py::arg("kT") = 1.0,
          py::arg("mass") = 1.0, py::arg("quantity") = "speed");
  // VACF and MSD: a (frames, n, dim) series in, one correlation out.
  const auto correlation = [](std::vector<double> (*f)(const std::vector<double>&, std::size_t,
                                                       std::size_t, int, std::size_t)) {
    return [f](const py::handle& x, const py::object& max_lag) {
      std::size_t frames = 0, n = 0;
      int dim = 0;
      const auto s = series(x, frames, n, dim);
      return to_numpy(f(s, frames, n, dim, max_lag_of(max_lag, frames)));
    };
  };
  m.def("vacf", correlation(&analysis::vacf), py::arg("velocities"),
        py::arg("max_lag") = py::none());
  m.def("msd", correlation(&analysis::msd), py::arg("positions"),
        py::arg("max_lag") = py::none());
}

}  // namespace hypergas::python
