// python/src/bind_observers.cpp -- the command's recorders as Python observers: Observer,
// MomentsRecorder (the rows of moments.csv, histograms), VacfRecorder, TransportRecorder
// (Green-Kubo coefficients, transport.csv), and for EDMD HelfandRecorder (Einstein-Helfand
// transport) and StructureRecorder (g(r), S(k)).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

#ifdef HYPERGAS_H5MD
#include "trajectory_observer.hpp"
#endif
#include "arrays.hpp"
#include "bindings.hpp"
#include "convert.hpp"
#include "hypergas/analysis/helfand_recorder.hpp"
#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/pressure_tensor_recorder.hpp"
#include "hypergas/analysis/structure_recorder.hpp"
#include "hypergas/analysis/transport_recorder.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "hypergas/error.hpp"
#include "hypergas/options/run_options.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/observer.hpp"

namespace hypergas::python {
namespace {

py::dict histogram_dict(const analysis::Histogram& h, const analysis::MaxwellReference& ref) {
  const std::size_t b = h.bins();
  py::array_t<double> lo(b), hi(b), count(b), density(b), mb(b);
  for (std::size_t i = 0; i < b; ++i) {
    lo.mutable_at(i) = h.lower(i);
    hi.mutable_at(i) = h.upper(i);
    count.mutable_at(i) = h.count(i);
    density.mutable_at(i) = h.density(i);
    mb.mutable_at(i) = analysis::bin_density(ref, h.lower(i), h.upper(i));  // as in the CSV
  }
  py::dict d;
  d["lo"] = lo, d["hi"] = hi, d["count"] = count, d["density"] = density;
  d["maxwell_density"] = mb, d["kT"] = ref.kT, d["mass"] = ref.mass, d["dim"] = ref.dim;
  d["underflow"] = h.underflow(), d["overflow"] = h.overflow();
  return d;
}

/// A recorder's rows as an (observations, columns) array.
py::array_t<double> rows_array(const std::vector<std::vector<double>>& rows, std::size_t c) {
  py::array_t<double> a({rows.size(), c});
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < c; ++j) a.mutable_at(i, j) = rows[i][j];
  return a;
}

}  // namespace

void bind_observers(py::module_& m) {
  py::class_<Observer>(m, "Observer");
  py::class_<analysis::MomentsRecorder, Observer>(m, "MomentsRecorder")
      .def(py::init([](const py::object& bins, const py::object& ks_sample,
                       const py::object& ks_seed, const py::object& threads) {
             const long long b = as_integer("bins", bins);
             const long long k = as_integer("ks_sample", ks_sample);
             if (b < 1 || b > 100000000)
               throw InvalidInput("bins must be in 1..1e8, got " + std::to_string(b));
             if (k < 0) throw InvalidInput("ks_sample must be >= 0, got " + std::to_string(k));
             const long long t = as_integer("threads", threads);
             options::check_threads(t, "threads");
             auto r = std::make_unique<analysis::MomentsRecorder>(
                 static_cast<std::size_t>(b), static_cast<std::size_t>(k), as_seed(ks_seed));
             r->set_threads(static_cast<int>(t));
             return r;
           }),
           py::arg("bins") = 50,
           py::arg("ks_sample") = analysis::MomentsRecorder::default_ks_cap,
           py::arg("ks_seed") = analysis::MomentsRecorder::default_ks_seed,
           py::arg("threads") = 1)
      .def_property_readonly("threads", &analysis::MomentsRecorder::threads)
      .def_property_readonly("columns", &analysis::MomentsRecorder::columns)
      .def_property_readonly("rows",
                             [](const analysis::MomentsRecorder& r) {
                               return rows_array(r.rows(), r.columns().size());
                             })
      .def("column", [](const analysis::MomentsRecorder& r,
                        const std::string& name) { return to_numpy(r.column(name)); })
      .def("histogram",
           [](const analysis::MomentsRecorder& r, int species) {
             return histogram_dict(r.last_histogram(species), r.last_reference(species));
           },
           py::arg("species") = -1)
      .def("observe_array",
           [](analysis::MomentsRecorder& r, const py::handle& v, const py::handle& masses,
              double time) {
             ArraySnapshot a = array_snapshot(v, masses, time);
             r.observe(a.s);
           },
           py::arg("velocities"), py::arg("masses") = py::none(), py::arg("time") = 0.0)
      .def("write_moments_csv", &analysis::MomentsRecorder::write_moments_csv)
      .def("write_speed_histogram_csv", &analysis::MomentsRecorder::write_speed_histogram_csv,
           py::arg("path"), py::arg("species") = -1);

  py::class_<analysis::PressureTensorRecorder, Observer>(m, "PressureTensorRecorder")
      .def(py::init([](const py::object& dim, const py::object& shear_rate,
                       const std::string& model, const py::object& vhs_exponent) {
             const long long d = as_integer("dim", dim);
             if (d < 2 || d > 6) throw InvalidInput("dim must be in 2..6, got " + std::to_string(d));
             const registry::ModelTraits t =
                 registry::model_traits(model, as_real("vhs_exponent", vhs_exponent));
             return std::make_unique<analysis::PressureTensorRecorder>(
                 static_cast<int>(d), as_real("shear_rate", shear_rate), t.exponent);
           }),
           py::arg("dim"), py::arg("shear_rate") = 0.0, py::arg("model") = "hs",
           py::arg("vhs_exponent") = 0.5)
      .def_property_readonly("columns", &analysis::PressureTensorRecorder::columns)
      .def_property_readonly("rows", [](const analysis::PressureTensorRecorder& r) {
        return rows_array(r.rows(), r.columns().size());
      });

  py::class_<analysis::VacfRecorder, Observer>(m, "VacfRecorder")
      .def(py::init([](const py::object& max_particles) {
             const long long k = as_integer("max_particles", max_particles);
             if (k < 1) throw InvalidInput("max_particles must be >= 1, got " + std::to_string(k));
             return std::make_unique<analysis::VacfRecorder>(static_cast<std::size_t>(k));
           }),
           py::arg("max_particles") = 1000)
      .def_property_readonly("frames", &analysis::VacfRecorder::frames)
      .def_property_readonly("particles", &analysis::VacfRecorder::particles)
      .def_property_readonly("dt", &analysis::VacfRecorder::dt)
      .def_property_readonly("has_positions", &analysis::VacfRecorder::has_positions)
      .def("lags",
           [](const analysis::VacfRecorder& r, std::size_t max_lag) {
             const auto l = r.lags(max_lag);
             return py::array_t<std::uint64_t>(static_cast<py::ssize_t>(l.size()),
                                               reinterpret_cast<const std::uint64_t*>(l.data()));
           },
           py::arg("max_lag") = 0)
      .def("vacf", [](const analysis::VacfRecorder& r,
                      std::size_t max_lag) { return to_numpy(r.vacf(max_lag)); },
           py::arg("max_lag") = 0)
      .def("msd", [](const analysis::VacfRecorder& r,
                     std::size_t max_lag) { return to_numpy(r.msd(max_lag)); },
           py::arg("max_lag") = 0)
      .def("green_kubo", &analysis::VacfRecorder::green_kubo, py::arg("max_lag") = 0)
      // the command's diffusion_* keys (sim/outputs/vacf.cpp): one estimator
      .def("diffusion",
           [](const analysis::VacfRecorder& r, double mean_free_time) {
             const analysis::VacfRecorder::Diffusion d = r.diffusion(mean_free_time);
             py::dict out;
             out["green_kubo"] = d.green_kubo, out["error"] = d.error;
             out["statistical_error"] = d.statistical_error;
             out["truncation_error"] = d.truncation_error, out["cut_time"] = d.cut_time;
             out["einstein"] = d.einstein, out["einstein_error"] = d.einstein_error;
             out["reached"] = d.reached;
             return out;
           },
           py::arg("mean_free_time"))
      .def("write_csv", &analysis::VacfRecorder::write_csv, py::arg("path"),
           py::arg("max_lag") = 0);

  py::class_<analysis::TransportRecorder, Observer>(m, "TransportRecorder")
      .def(py::init([](const py::object& dim, const py::object& n, double until, double dt,
                       double max_lag, const py::object& tagged, double warmup,
                       const std::string& model, double vhs_exponent, const py::object& seed) {
             const long long d = as_integer("dim", dim), nn = as_integer("n", n);
             const long long t = as_integer("tagged", tagged);
             options::check_dim(static_cast<int>(d), "dim");
             options::check_n(nn, "n");
             if (!(std::isfinite(until) && std::isfinite(dt) && dt > 0.0 && dt <= 1.0))
               throw InvalidInput("dt must be finite, > 0 and at most 1; until finite");
             if (!(std::isfinite(warmup) && warmup >= 0.0))
               throw InvalidInput("warmup must be finite and >= 0");
             if (!(std::isfinite(max_lag) && max_lag >= 4.0 * dt && max_lag <= 1e4))
               throw InvalidInput("max_lag must be at least 4 dt and at most 1e4");
             if (t < 0 || t > 4096)
               throw InvalidInput("tagged must be in 0..4096 (0: no self-diffusion, as the "
                                  "lanes scheme needs)");
             if (!(until - warmup >= 10.0 * max_lag))
               throw InvalidInput("until must be at least warmup + 10 max_lag (ten correlation "
                                  "windows)");
             analysis::TransportSettings ts;
             ts.dt = dt, ts.max_lag = max_lag, ts.tagged = static_cast<int>(t);
             ts.warmup = warmup, ts.seed = as_seed(seed);
             const auto frames =
                 static_cast<std::uint64_t>(std::llround((until - warmup) / dt)) + 1;
             const registry::ModelTraits m = registry::model_traits(model, vhs_exponent);
             return std::make_unique<analysis::TransportRecorder>(
                 ts, static_cast<int>(d), static_cast<std::size_t>(nn), frames,
                 analysis::CollisionLaw{m.exponent, m.isotropic_scattering});
           }),
           py::arg("dim"), py::arg("n"), py::arg("until"), py::arg("dt") = 0.05,
           py::arg("max_lag") = 40.0, py::arg("tagged") = 32, py::arg("warmup") = 20.0,
           py::arg("model") = "hs", py::arg("vhs_exponent") = 1.0, py::arg("seed") = 1)
      .def_property_readonly("frames", &analysis::TransportRecorder::frames)
      .def_property_readonly("dt", &analysis::TransportRecorder::dt)
      .def_property_readonly("kT", &analysis::TransportRecorder::kT)
      .def("finish",
           [](analysis::TransportRecorder& r) {
             py::dict out;
             for (const auto& c : r.finish()) {
               py::dict d;
               d["value"] = c.value, d["error"] = c.error, d["first_sonine"] = c.sonine;
               d["ratio"] = c.ratio, d["ratio_error"] = c.ratio_error, d["t_cut"] = c.t_cut;
               d["tail"] = c.tail, d["c0"] = c.c0, d["decay_rate"] = c.rate;
               d["decay_rate_error"] = c.rate_error, d["first_sonine_rate"] = c.sonine_rate;
               d["stretches"] = to_numpy(c.stretches);
               out[py::str(c.name)] = d;
             }
             return out;
           })
      .def("normalised",
           [](const analysis::TransportRecorder& r, int g) {
             if (g < 0 || g > 2) throw InvalidInput("normalised: group must be 0, 1 or 2");
             return to_numpy(r.normalised(g));
           },
           py::arg("group"))
      .def("write_transport_csv", &analysis::TransportRecorder::write_transport_csv,
           py::arg("path"))
      .def("write_correlations_csv", &analysis::TransportRecorder::write_correlations_csv,
           py::arg("path"));

#ifdef HYPERGAS_H5MD
  // engine.run(..., trajectory=PATH): H5MD frames at the run's sampling instants
  py::class_<cli::TrajectoryObserver, Observer>(m, "TrajectoryRecorder")
      .def(py::init([](const std::string& path, bool ids,
                       const std::vector<std::pair<std::string, std::string>>& params) {
             if (path.empty()) throw InvalidInput("trajectory: the path is empty");
             return std::make_unique<cli::TrajectoryObserver>(path, 1, ids, params);
           }),
           py::arg("path"), py::arg("ids") = true,
           py::arg("parameters") = std::vector<std::pair<std::string, std::string>>{})
      .def("close", [](cli::TrajectoryObserver& t) { return t.close().string(); })
      .def_property_readonly("frames", &cli::TrajectoryObserver::frames);
#endif

  py::class_<analysis::HelfandRecorder, Observer>(m, "HelfandRecorder")
      .def(py::init([](const py::object& dim, const py::object& n, double start, double end,
                       double dt, double max_lag, const py::object& tagged, double window) {
             const long long d = as_integer("dim", dim), nn = as_integer("n", n);
             const long long t = as_integer("tagged", tagged);
             options::check_dim(static_cast<int>(d), "dim");
             options::check_n(nn, "n");
             if (!(std::isfinite(dt) && dt > 0.0 && dt <= 1.0))
               throw InvalidInput("dt must be finite, > 0 and at most 1 (mean free times)");
             if (!(std::isfinite(max_lag) && max_lag >= 4.0 * dt && max_lag <= 1e4))
               throw InvalidInput("max_lag must be at least 4 dt and at most 1e4");
             if (t < 1 || t > 4096) throw InvalidInput("tagged must be in 1..4096");
             if (!(std::isfinite(window) && window > 0.0))
               throw InvalidInput("window must be finite and > 0");
             analysis::TransportSettings ts;
             ts.dt = dt, ts.max_lag = max_lag, ts.tagged = static_cast<int>(t);
             ts.window = window;
             return std::make_unique<analysis::HelfandRecorder>(
                 ts, static_cast<int>(d), static_cast<std::size_t>(nn), start, end);
           }),
           py::arg("dim"), py::arg("n"), py::arg("start"), py::arg("end"), py::arg("dt") = 0.05,
           py::arg("max_lag") = 40.0, py::arg("tagged") = options::edmd_tagged,
           py::arg("window") = 3.0)
      .def_property_readonly("frames", &analysis::HelfandRecorder::frames)
      .def_property_readonly("dt", &analysis::HelfandRecorder::dt)
      .def_property_readonly("mean_free_time", &analysis::HelfandRecorder::mean_free_time)
      .def_property_readonly("kT", &analysis::HelfandRecorder::kT)
      .def_property_readonly("chi", &analysis::HelfandRecorder::chi)
      .def_property_readonly("packing", &analysis::HelfandRecorder::packing)
      .def("finish",
           [](analysis::HelfandRecorder& r) {
             py::dict out;
             for (const auto& c : r.finish()) {
               py::dict d;
               d["value"] = c.value, d["error"] = c.error, d["first_sonine"] = c.sonine;
               d["ratio"] = c.ratio, d["ratio_error"] = c.ratio_error, d["enskog"] = c.enskog;
               d["enskog_ratio"] = c.enskog_ratio, d["enskog_ratio_error"] = c.enskog_ratio_error;
               d["t_cut"] = c.t_cut, d["tail"] = c.tail, d["c0"] = c.c0;
               d["statistical_error"] = c.statistical_error;
               d["truncation_error"] = c.truncation_error;
               d["stretches"] = to_numpy(c.stretches);
               out[py::str(c.name)] = d;
             }
             return out;
           })
      .def("write_transport_csv", &analysis::HelfandRecorder::write_transport_csv,
           py::arg("path"))
      .def("write_correlations_csv", &analysis::HelfandRecorder::write_correlations_csv,
           py::arg("path"));

  py::class_<analysis::StructureRecorder, Observer>(m, "StructureRecorder")
      .def(py::init([](const py::object& dim, const py::object& n, double start, double r_max,
                       double dr, double k_max, const py::object& vectors_per_shell,
                       const py::object& seed) {
             const long long d = as_integer("dim", dim), nn = as_integer("n", n);
             options::check_dim(static_cast<int>(d), "dim");
             options::check_n(nn, "n");
             analysis::StructureSettings ss;
             ss.r_max = r_max, ss.dr = dr, ss.k_max = k_max;
             const long long v = as_integer("vectors_per_shell", vectors_per_shell);
             if (v < 1 || v > 100000) throw InvalidInput("vectors_per_shell must be in 1..1e5");
             ss.vectors_per_shell = static_cast<int>(v);
             ss.seed = as_seed(seed);
             return std::make_unique<analysis::StructureRecorder>(
                 ss, static_cast<int>(d), static_cast<std::size_t>(nn), start);
           }),
           py::arg("dim"), py::arg("n"), py::arg("start") = 0.0, py::arg("r_max") = 5.0,
           py::arg("dr") = 0.02, py::arg("k_max") = 15.0, py::arg("vectors_per_shell") = 24,
           py::arg("seed") = 1)
      .def_property_readonly("frames", &analysis::StructureRecorder::frames)
      .def("finish",
           [](analysis::StructureRecorder& r) {
             const analysis::StructureResult& s = r.finish();
             py::dict out;
             out["r"] = to_numpy(s.r), out["g"] = to_numpy(s.g), out["g_error"] = to_numpy(s.g_error);
             out["k"] = to_numpy(s.k), out["S"] = to_numpy(s.s), out["S_error"] = to_numpy(s.s_error);
             out["contact"] = s.contact, out["contact_error"] = s.contact_error;
             out["r_max"] = s.r_max, out["frames"] = s.frames;
             return out;
           })
      .def("write_rdf_csv", &analysis::StructureRecorder::write_rdf_csv, py::arg("path"))
      .def("write_structure_factor_csv",
           &analysis::StructureRecorder::write_structure_factor_csv, py::arg("path"));
}

}  // namespace hypergas::python
