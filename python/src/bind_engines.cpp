// python/src/bind_engines.cpp -- the class Engine (both engines behind one Python type), its
// factories make_dsmc, make_dsmc_from, make_edmd, and the DSMC- and EDMD-only functions.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "convert.hpp"
#include "engine_box.hpp"
#include "engine_handle.hpp"
#include "hypergas/error.hpp"
#include "hypergas/geometry.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/registry.hpp"
#include "keywords.hpp"

namespace hypergas::python {
namespace {

/// A new engine box holding a DSMC engine set to run on `threads` threads.
std::unique_ptr<EngineBox> dsmc_box(std::unique_ptr<DsmcHandle> h, int threads) {
  h->set_threads(threads);
  auto box = std::make_unique<EngineBox>();
  box->h = std::move(h);
  return box;
}

/// The DSMC and EDMD extras live on the same Python type: TypeError for the other engine.
DsmcHandle& dsmc_of(const EngineBox& b) {
  auto* d = dynamic_cast<DsmcHandle*>(b.h.get());
  if (!d) throw py::type_error("not a DSMC engine");
  return *d;
}
EdmdHandle& edmd_of(const EngineBox& b) {
  auto* e = dynamic_cast<EdmdHandle*>(b.h.get());
  if (!e) throw py::type_error("not an EDMD engine");
  return *e;
}

/// hypergas.DSMC.from_velocities: a DSMC engine from given velocities (n x dim, total
/// momentum zero) and optional species indices; the other keywords as run_options reads.
std::unique_ptr<EngineBox> dsmc_from(const py::handle& velocities, const py::handle& species,
                                     const py::kwargs& kw) {
  auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(velocities);
  if (!v) type_error("velocities must be an array of numbers, shape (n, dim)");
  if (v.ndim() != 2)
    throw InvalidInput("velocities must have shape (n, dim), got " + std::to_string(v.ndim()) +
                       " dimensions");
  py::kwargs all = kw;
  all["n"] = py::int_(v.shape(0));
  all["dim"] = py::int_(v.shape(1));
  std::vector<std::string> allowed = engine_keywords(registry::EngineKind::dsmc, true);
  allowed.insert(allowed.end(), {"n", "dim"});
  options::RunOptions o = run_options(registry::EngineKind::dsmc, all, allowed);
  const auto n = static_cast<std::size_t>(v.shape(0));
  const int dim = static_cast<int>(v.shape(1));
  const double* x = v.data();
  check_finite_rows(x, n, dim, static_cast<std::size_t>(dim));
  std::vector<std::uint8_t> sp;
  if (!species.is_none()) {
    auto a = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(species);
    if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n)
      throw InvalidInput("species must be a 1-d array of n = " + std::to_string(n) + " indices");
    for (std::size_t i = 0; i < n; ++i) {
      if (a.data()[i] != 0 && a.data()[i] != 1)
        throw InvalidInput("species must be 0 or 1 (particle " + std::to_string(i) + ")");
      sp.push_back(static_cast<std::uint8_t>(a.data()[i]));
    }
    if (!options::two_species(o))
      throw InvalidInput("species needs mass_ratio != 1 (the mass of species 1)");
  } else if (options::two_species(o)) {
    throw InvalidInput("mass_ratio needs species (which particles have that mass)");
  }
  // The engine refuses a non-zero total momentum (dsmc/time_unit.hpp: the time unit is
  // defined in the centre-of-mass frame).
  const GivenVelocities given{x, n, sp.empty() ? nullptr : sp.data()};
  return dsmc_box(make_dsmc(o, &given), o.threads);
}

/// hypergas.EDMD.from_state: an EDMD engine from given positions and velocities (n x dim)
/// in the periodic cube of side `box` (positions are wrapped into it); the packing follows
/// from N and the box. The other keywords as run_options reads, less the start's.
std::unique_ptr<EngineBox> edmd_from(const py::handle& positions, const py::handle& velocities,
                                     double box, const py::kwargs& kw) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  auto x = Array::ensure(positions), v = Array::ensure(velocities);
  if (!x || !v) type_error("positions and velocities must be arrays of numbers, shape (n, dim)");
  if (x.ndim() != 2 || v.ndim() != 2 || x.shape(0) != v.shape(0) || x.shape(1) != v.shape(1))
    throw InvalidInput("positions and velocities must have the same shape (n, dim)");
  if (!(std::isfinite(box) && box > 0.0)) throw InvalidInput("box must be a finite side > 0");
  const auto n = static_cast<std::size_t>(x.shape(0));
  const int dim = static_cast<int>(x.shape(1));
  options::check_dim(dim, "dim");
  options::check_n(static_cast<long long>(n), "n");
  std::vector<double> wrapped(x.data(), x.data() + n * std::size_t(dim));
  for (double& q : wrapped) {
    if (!std::isfinite(q)) throw InvalidInput("positions must be finite");
    q -= box * std::floor(q / box);
    if (q >= box) q = 0.0;
  }
  for (const char* k : {"n", "dim", "packing"})  // from the state
    if (kw.contains(k)) throw InvalidInput(std::string(k) + " follows from the state: leave it out");
  py::kwargs all = kw;
  all["n"] = py::int_(n);
  all["dim"] = py::int_(dim);
  all["packing"] = py::float_(static_cast<double>(n) * ball_volume(dim, 1.0) / std::pow(box, dim));
  std::vector<std::string> allowed;
  for (const std::string& k : engine_keywords(registry::EngineKind::edmd, true))
    if (k != "packing" && k != "start_packing") allowed.push_back(k);
  allowed.insert(allowed.end(), {"n", "dim", "packing"});
  options::RunOptions o = run_options(registry::EngineKind::edmd, all, allowed);
  const edmd::GivenState g{wrapped.data(), v.data(), n, box, nullptr};
  auto out = std::make_unique<EngineBox>();
  {
    py::gil_scoped_release nogil;
    out->h = make_edmd(o, &g);
  }
  return out;
}

}  // namespace

void bind_engines(py::module_& m) {
  py::class_<EngineBox>(m, "Engine")
      .def_property_readonly("dim", [](const EngineBox& b) { return b.h->dim(); })
      .def_property_readonly("n", [](const EngineBox& b) { return b.h->size(); })
      .def_property_readonly("time", [](const EngineBox& b) { return b.h->time(); })
      .def_property_readonly("collisions", [](const EngineBox& b) { return b.h->collisions(); })
      .def_property_readonly("bytes_per_particle",
                             [](const EngineBox& b) { return b.h->bytes_per_particle(); })
      .def_property_readonly("velocities",
                             [](py::object self) {
                               const EngineBox& b = self.cast<const EngineBox&>();
                               b.idle();
                               return view(b.h->velocities(), b.h->size(), b.h->dim(), self);
                             })
      .def_property_readonly("species",
                             [](py::object self) -> py::object {
                               const EngineBox& b = self.cast<const EngineBox&>();
                               const std::uint8_t* s = b.h->species();
                               if (!s) return py::none();
                               return view_1d(s, b.h->size(), self);
                             })
      .def_property_readonly("species_masses",
                             [](const EngineBox& b) { return to_numpy(b.h->species_masses()); })
      .def_property_readonly("kinetic_energy", [](const EngineBox& b) {
        b.idle();
        return b.h->kinetic_energy();
      })
      .def_property_readonly("momentum", [](const EngineBox& b) {
        b.idle();
        return to_numpy(b.h->momentum());
      })
      .def_property_readonly("_velocity_address",  // for the zero-copy test
                             [](const EngineBox& b) {
                               return reinterpret_cast<std::uintptr_t>(b.h->velocities().data);
                             })
      .def("advance", &advance, py::arg("t"), py::arg("progress") = py::none())
      .def("observe", [](EngineBox& b, Observer& obs) {
        b.idle();
        b.h->observe(obs);
      });

  m.def("make_dsmc", [](const py::kwargs& kw) {
    const options::RunOptions o = run_options(registry::EngineKind::dsmc, kw, engine_keywords(registry::EngineKind::dsmc, false));
    return dsmc_box(make_dsmc(o), o.threads);
  });
  m.def("make_dsmc_from", &dsmc_from, py::arg("velocities"), py::arg("species") = py::none());
  m.def("make_edmd_from", &edmd_from, py::arg("positions"), py::arg("velocities"), py::arg("box"));
  m.def("make_edmd", [](const py::kwargs& kw) {
    const options::RunOptions o = run_options(registry::EngineKind::edmd, kw, engine_keywords(registry::EngineKind::edmd, false));
    auto box = std::make_unique<EngineBox>();
    {
      py::gil_scoped_release nogil;  // a dense start compresses for a while
      box->h = make_edmd(o);
    }
    return box;
  });
  m.def("set_threads", [](EngineBox& b, const py::object& t) {
    b.idle();
    const long long k = as_integer("threads", t);
    options::check_threads(k, "--threads");
    dsmc_of(b).set_threads(static_cast<int>(k));
  });
  m.def("threads", [](const EngineBox& b) { return dsmc_of(b).threads(); });
  m.def("candidates", [](const EngineBox& b) { return dsmc_of(b).candidates(); });
  m.def("model", [](const EngineBox& b) { return std::string(dsmc_of(b).model()); });
  m.def("positions", [](py::object self) {
    EngineBox& b = self.cast<EngineBox&>();
    b.idle();
    return view(edmd_of(b).positions(), b.h->size(), b.h->dim(), self);
  });
  m.def("ids", [](py::object self) {
    const EngineBox& b = self.cast<const EngineBox&>();
    return view_1d(edmd_of(b).ids(), b.h->size(), self);
  });
  m.def("unwrapped_positions", [](const EngineBox& b) {
    b.idle();
    py::array_t<double> a(
        {static_cast<py::ssize_t>(b.h->size()), static_cast<py::ssize_t>(b.h->dim())});
    const auto x = edmd_of(b).unwrapped_positions();
    std::memcpy(a.mutable_data(), x.data(), x.size() * sizeof(double));
    return a;
  });
  m.def("edmd_observables", [](const EngineBox& b) {
    b.idle();
    const EdmdHandle& e = edmd_of(b);
    py::dict d;
    d["box_side"] = e.box_side(), d["packing"] = e.packing(), d["temperature"] = e.temperature();
    // Z = PV/(N kT) is an equilibrium measurement: NaN in a granular or sheared gas
    d["pressure_Z"] = e.pressure_Z_or_nan();
    d["collision_rate"] = e.collision_rate();
    d["restitution"] = e.restitution(), d["tc_time"] = e.tc_time();
    d["tc_elastic_collisions"] = e.tc_elastic_collisions();
    d["mean_free_time"] = e.mean_free_time();
    return d;
  });
  m.def("set_restitution", [](EngineBox& b, const py::object& alpha) {
    b.idle();
    return edmd_of(b).set_restitution(as_real("restitution", alpha));
  });
  m.def("dsmc_granular", [](const EngineBox& b) {
    b.idle();
    const DsmcHandle& d = dsmc_of(b);
    py::dict g;
    g["restitution"] = d.restitution(), g["real_time"] = d.real_time();
    g["log_velocity_scale"] = d.log_velocity_scale(), g["kicks"] = d.kicks();
    return g;
  });
  m.def("reset_observables", [](EngineBox& b) {
    b.idle();
    edmd_of(b).reset_observables();
  });
}

}  // namespace hypergas::python
