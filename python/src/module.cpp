// python/src/module.cpp -- the extension module `hypergas._hypergas`: the engines, the
// analysis recorders and the studies, bound with pybind11. The Python package
// (python/hypergas/__init__.py) builds the public API on top of it.
//
// Conventions of the bindings:
//  - Options are validated by the command's own code (sim/options.cpp, cli::validate), so
//    a bad value gets the command's message with the Python spelling of the option
//    ("--mass-ratio" becomes "mass_ratio"); InvalidInput becomes ValueError, a value of
//    the wrong type TypeError.
//  - Per-particle arrays are numpy views of the engine's memory (no copy), read-only, and
//    keep the engine alive. Engine calls that could move or change that memory while a
//    run is in progress on another Python thread raise RuntimeError instead.
//  - advance() releases the GIL; every ~0.1 s of wall time it takes the GIL back to let
//    Python handle signals (Ctrl-C raises KeyboardInterrupt with the engine consistent at
//    the time reached) and to call the progress function.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "engine_handle.hpp"
#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/vacf.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "hypergas/edmd/box.hpp"
#include "hypergas/error.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/studies/report.hpp"

namespace py = pybind11;

namespace hypergas::python {
namespace {

/// "--mass-ratio must be ..." -> "mass_ratio must be ...": the command's messages in the
/// spelling of the Python keyword arguments.
std::string python_spelling(const std::string& msg) {
  const auto lower = [](char c) { return c >= 'a' && c <= 'z'; };
  const auto word = [&](char c) { return lower(c) || (c >= '0' && c <= '9'); };
  std::string out;
  for (std::size_t i = 0; i < msg.size();) {
    // "--" followed by a lowercase letter starts an option name: words joined by '-'
    if (msg.compare(i, 2, "--") == 0 && i + 2 < msg.size() && lower(msg[i + 2])) {
      std::size_t j = i + 2;
      while (j < msg.size() && (word(msg[j]) || (msg[j] == '-' && j + 1 < msg.size() &&
                                                 word(msg[j + 1]))))
        out += msg[j] == '-' ? '_' : msg[j], ++j;
      i = j;
    } else {
      out += msg[i++];
    }
  }
  return out;
}

[[noreturn]] void type_error(const std::string& msg) { throw py::type_error(msg); }

std::string type_name(const py::handle& h) { return py::str(py::type::handle_of(h).attr("__name__")); }

/// An integer argument: Python ints, numpy integers, and floats with an integral value
/// (1e6); bool is refused.
long long as_integer(const std::string& name, const py::handle& h) {
  if (PyBool_Check(h.ptr())) type_error(name + " must be an integer, got bool");
  if (PyFloat_Check(h.ptr())) {
    const double d = h.cast<double>();
    if (!(std::isfinite(d) && d == std::floor(d) && std::fabs(d) < 9.0e18))
      throw InvalidInput(name + " must be an integer, got " + std::string(py::repr(h)));
    return static_cast<long long>(d);
  }
  if (!PyIndex_Check(h.ptr())) type_error(name + " must be an integer, got " + type_name(h));
  py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(h.ptr()));
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
  if (overflow) throw InvalidInput(name + " is out of range: " + std::string(py::repr(h)));
  return v;
}

std::uint64_t as_seed(const py::handle& h) {
  if (PyBool_Check(h.ptr()) || !PyIndex_Check(h.ptr()))
    type_error("seed must be an integer in 0..2^64-1, got " + type_name(h));
  py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(h.ptr()));
  const unsigned long long v = PyLong_AsUnsignedLongLong(i.ptr());
  if (PyErr_Occurred()) {
    PyErr_Clear();
    throw InvalidInput("seed must be an integer in 0..2^64-1, got " + std::string(py::repr(h)));
  }
  return v;
}

/// A real argument: int, float or numpy scalar; strings and bools are refused.
double as_real(const std::string& name, const py::handle& h) {
  if (PyBool_Check(h.ptr()) || PyUnicode_Check(h.ptr()) || PyBytes_Check(h.ptr()))
    type_error(name + " must be a number, got " + type_name(h));
  PyObject* f = PyNumber_Float(h.ptr());
  if (!f) {
    PyErr_Clear();
    type_error(name + " must be a number, got " + type_name(h));
  }
  const double d = PyFloat_AsDouble(f);
  Py_DECREF(f);
  return d;
}

std::string as_text(const std::string& name, const py::handle& h) {
  if (!PyUnicode_Check(h.ptr())) type_error(name + " must be a string, got " + type_name(h));
  return h.cast<std::string>();
}

/// The keyword arguments of hypergas.DSMC / hypergas.EDMD as the command's run options,
/// validated by cli::validate. Keywords not in `allowed` raise TypeError (as Python does).
cli::RunOptions run_options(registry::EngineKind kind, const py::kwargs& kw,
                            const std::vector<std::string>& allowed) {
  cli::RunOptions o;
  o.engine = std::string(registry::name(kind));
  o.out = "python";  // no output folder: the module writes nothing by itself
  for (const auto& [key, value] : kw) {
    const std::string k = py::str(key);
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
      type_error("unexpected keyword argument '" + k + "'");
    if (value.is_none()) continue;  // not given: the default
    std::string option = "--" + k;
    for (char& c : option)
      if (c == '_') c = '-';
    o.given.push_back(option);
    if (k == "dim") o.dim = static_cast<int>(std::clamp<long long>(as_integer(k, value), -1, 1000));
    else if (k == "n") o.n = as_integer(k, value);
    else if (k == "model") o.model = as_text(k, value);
    else if (k == "init") o.init = as_text(k, value);
    else if (k == "vhs_exponent") o.vhs_exponent = as_real(k, value);
    else if (k == "packing") o.packing = as_real(k, value);
    else if (k == "start_packing") o.start_packing = as_real(k, value);
    else if (k == "mass_ratio") o.mass_ratio = as_real(k, value);
    else if (k == "fraction") o.fraction = as_real(k, value);
    else if (k == "temperature") o.temperature = as_real(k, value);
    else if (k == "seed") o.seed = as_seed(value);
    else if (k == "threads")
      o.threads = static_cast<int>(std::clamp<long long>(as_integer(k, value), -1, 100000));
  }
  cli::validate(o);
  return o;
}

/// A read-only numpy view of `rows` (n x cols doubles, `stride` doubles apart), owned by
/// `base`.
py::array view(const Rows& rows, std::size_t n, int cols, py::handle base) {
  py::array a(py::dtype::of<double>(), {n, static_cast<std::size_t>(cols)},
              {static_cast<py::ssize_t>(rows.stride * sizeof(double)),
               static_cast<py::ssize_t>(sizeof(double))},
              rows.data, base);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

template <class T>
py::array view_1d(const T* data, std::size_t n, py::handle base) {
  py::array a(py::dtype::of<T>(), {n}, {static_cast<py::ssize_t>(sizeof(T))}, data, base);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

py::array_t<double> to_numpy(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

/// A Python exception raised inside a poll, carried through the engine as a C++ exception
/// and restored once the GIL is held again.
struct PythonStop {};

/// The Python object of an engine and its busy flag: one call at a time may run it.
struct EngineBox {
  std::unique_ptr<EngineHandle> h;
  std::atomic<bool> busy{false};
  [[noreturn]] static void refuse() {
    throw std::runtime_error("the engine is running (one call at a time)");
  }
  /// Throws RuntimeError while a run is in progress.
  void idle() const {
    if (busy) refuse();
  }
};

/// Marks an engine busy while a run is in progress (RuntimeError for a second caller).
class Busy {
 public:
  explicit Busy(EngineBox& box) : flag_(box.busy) {
    if (flag_.exchange(true)) EngineBox::refuse();
  }
  ~Busy() { flag_ = false; }
  Busy(const Busy&) = delete;
  Busy& operator=(const Busy&) = delete;

 private:
  std::atomic<bool>& flag_;
};

/// A new engine box holding a DSMC engine set to run on `threads` threads.
std::unique_ptr<EngineBox> dsmc_box(std::unique_ptr<DsmcHandle> h, int threads) {
  h->set_threads(threads);
  auto box = std::make_unique<EngineBox>();
  box->h = std::move(h);
  return box;
}

/// Throws InvalidInput naming the particle unless rows x 0..cols-1 (`stride` apart) are
/// finite.
void check_finite_rows(const double* x, std::size_t rows, int cols, std::size_t stride) {
  for (std::size_t i = 0; i < rows; ++i)
    for (int k = 0; k < cols; ++k)
      if (!std::isfinite(x[i * stride + static_cast<std::size_t>(k)]))
        throw InvalidInput("velocities must be finite (particle " + std::to_string(i) + ")");
}

/// Advances box's engine to t with the GIL released (see the file comment). `progress`
/// (callable or None) is called with the engine time about every 0.1 s.
void advance(EngineBox& box, double t, const py::object& progress) {
  using Clock = std::chrono::steady_clock;
  Busy busy(box);
  PyObject *type = nullptr, *value = nullptr, *trace = nullptr;
  auto last = Clock::now();
  EngineHandle& h = *box.h;
  const std::function<void()> poll = [&] {
    const auto now = Clock::now();
    if (now - last < std::chrono::milliseconds(100)) return;
    last = now;
    py::gil_scoped_acquire gil;
    bool failed = PyErr_CheckSignals() != 0;
    if (!failed && !progress.is_none()) {
      PyObject* r = PyObject_CallOneArg(progress.ptr(), PyFloat_FromDouble(h.time()));
      failed = r == nullptr;
      Py_XDECREF(r);
    }
    if (failed) {
      PyErr_Fetch(&type, &value, &trace);
      throw PythonStop{};
    }
  };
  try {
    py::gil_scoped_release nogil;
    h.advance(t, poll);
  } catch (const PythonStop&) {
    PyErr_Restore(type, value, trace);
    throw py::error_already_set();
  }
}

/// A snapshot of a numpy array of velocities (n x D, float64, rows `stride` doubles apart,
/// components contiguous; anything else is copied into that form) and optional masses.
struct ArraySnapshot {
  py::array_t<double> v;  // keeps the data alive
  std::vector<double> inv_mass;
  Snapshot s;
};

ArraySnapshot array_snapshot(const py::handle& velocities, const py::handle& masses, double time) {
  ArraySnapshot a;
  py::array in = py::array::ensure(velocities);
  if (!in) type_error("velocities must be an array of numbers, shape (n, dim)");
  if (in.ndim() != 2)
    throw InvalidInput("velocities must have shape (n, dim), got " + std::to_string(in.ndim()) +
                       " dimensions");
  const bool direct = in.dtype().is(py::dtype::of<double>()) && in.strides(1) == sizeof(double) &&
                      in.strides(0) > 0 && in.strides(0) % sizeof(double) == 0 &&
                      in.strides(0) / static_cast<py::ssize_t>(sizeof(double)) >= in.shape(1);
  if (direct)
    a.v = py::reinterpret_borrow<py::array_t<double>>(in);
  else {
    if (in.dtype().kind() != 'f' && in.dtype().kind() != 'i' && in.dtype().kind() != 'u')
      type_error("velocities must be an array of numbers, got dtype " +
                 std::string(py::str(in.dtype())));
    a.v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(in);
  }
  const auto n = static_cast<std::size_t>(a.v.shape(0));
  const int dim = static_cast<int>(a.v.shape(1));
  if (dim < 1) throw InvalidInput("velocities must have at least one component");
  if (n < 2) throw InvalidInput("need at least 2 particles, got " + std::to_string(n));
  a.s.dim = dim;
  a.s.n = n;
  a.s.stride = static_cast<int>(a.v.strides(0) / static_cast<py::ssize_t>(sizeof(double)));
  a.s.velocities = a.v.data();
  a.s.time = time;
  check_finite_rows(a.s.velocities, n, dim, static_cast<std::size_t>(a.s.stride));
  if (!masses.is_none()) {
    auto m = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(masses);
    if (!m || m.ndim() != 1 || static_cast<std::size_t>(m.shape(0)) != n)
      throw InvalidInput("masses must be a 1-d array of n = " + std::to_string(n) + " numbers");
    a.inv_mass.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double mi = m.data()[i];
      if (!(std::isfinite(mi) && mi > 0.0))
        throw InvalidInput("masses must be finite and > 0 (particle " + std::to_string(i) + ")");
      a.inv_mass[i] = 1.0 / mi;
    }
    a.s.inv_mass = a.inv_mass.data();
  }
  return a;
}

analysis::Quantity quantity(const std::string& q) {
  if (q == "speed") return analysis::Quantity::speed;
  if (q == "component") return analysis::Quantity::component;
  if (q == "energy") return analysis::Quantity::energy;
  throw InvalidInput("unknown quantity '" + q + "' (known: speed, component, energy)");
}

/// f applied to every element of x (any shape), as a new float64 array.
template <class F>
py::array_t<double> elementwise(const py::handle& x, F f) {
  auto in = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(x);
  if (!in) type_error("x must be a number or an array of numbers");
  py::array_t<double> out(std::vector<py::ssize_t>(in.shape(), in.shape() + in.ndim()));
  const double* a = in.data();
  double* b = out.mutable_data();
  for (py::ssize_t i = 0; i < in.size(); ++i) b[i] = f(a[i]);
  return out;
}

/// A frames x n x D series (numpy) as the flat vector the FFT correlations read.
std::vector<double> series(const py::handle& x, std::size_t& frames, std::size_t& n, int& dim) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(x);
  if (!a || a.ndim() != 3)
    throw InvalidInput("the series must be an array of shape (frames, n, dim)");
  frames = static_cast<std::size_t>(a.shape(0));
  n = static_cast<std::size_t>(a.shape(1));
  dim = static_cast<int>(a.shape(2));
  if (frames < 2 || n < 1 || dim < 1)
    throw InvalidInput("the series needs at least 2 frames, 1 particle and 1 component");
  std::vector<double> v(a.data(), a.data() + a.size());
  for (double d : v)
    if (!std::isfinite(d)) throw InvalidInput("the series must be finite");
  return v;
}

std::size_t max_lag_of(const py::object& max_lag, std::size_t frames) {
  if (max_lag.is_none()) return frames / 2;
  const long long m = as_integer("max_lag", max_lag);
  if (m < 0 || static_cast<std::size_t>(m) >= frames)
    throw InvalidInput("max_lag must be in 0.." + std::to_string(frames - 1) + ", got " +
                       std::to_string(m));
  return static_cast<std::size_t>(m);
}

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

const std::vector<std::string> dsmc_keywords = {"dim",         "n",           "model",
                                                "vhs_exponent", "init",       "mass_ratio",
                                                "fraction",     "temperature", "seed",
                                                "threads"};
const std::vector<std::string> edmd_keywords = {"dim",        "n",        "packing",
                                                "start_packing", "init", "mass_ratio",
                                                "fraction",   "seed"};

}  // namespace
}  // namespace hypergas::python

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

  // ---- observers: the command's recorders
  py::class_<Observer>(m, "Observer");
  py::class_<analysis::MomentsRecorder, Observer>(m, "MomentsRecorder")
      .def(py::init([](const py::object& bins, const py::object& ks_sample,
                       const py::object& ks_seed, const py::object& threads) {
             const long long b = as_integer("bins", bins);
             const long long k = as_integer("ks_sample", ks_sample);
             if (b < 1 || b > 100000000)
               throw InvalidInput("bins must be in 1..1e8, got " + std::to_string(b));
             if (k < 1) throw InvalidInput("ks_sample must be >= 1, got " + std::to_string(k));
             const long long t = as_integer("threads", threads);
             if (t < 1 || t > 64) throw InvalidInput("threads must be in 1..64, got " + std::to_string(t));
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
                               const auto& rows = r.rows();
                               const std::size_t c = r.columns().size();
                               py::array_t<double> a({rows.size(), c});
                               for (std::size_t i = 0; i < rows.size(); ++i)
                                 for (std::size_t j = 0; j < c; ++j) a.mutable_at(i, j) = rows[i][j];
                               return a;
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
      .def("write_csv", &analysis::VacfRecorder::write_csv, py::arg("path"),
           py::arg("max_lag") = 0);

  // ---- engines
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

  // DSMC extras on the same Python type: they raise TypeError for an EDMD engine.
  const auto dsmc = [](const EngineBox& b) -> DsmcHandle& {
    auto* d = dynamic_cast<DsmcHandle*>(b.h.get());
    if (!d) throw py::type_error("not a DSMC engine");
    return *d;
  };
  const auto edmd = [](const EngineBox& b) -> EdmdHandle& {
    auto* e = dynamic_cast<EdmdHandle*>(b.h.get());
    if (!e) throw py::type_error("not an EDMD engine");
    return *e;
  };
  m.def("make_dsmc", [](const std::string& scheme, double dt, const py::kwargs& kw) {
    const cli::RunOptions o = run_options(registry::EngineKind::dsmc, kw, dsmc_keywords);
    return dsmc_box(make_dsmc(o, scheme, dt), o.threads);
  }, py::arg("scheme") = "exact", py::arg("dt") = 0.01);
  m.def("make_dsmc_from", [](const py::handle& velocities, const py::handle& species,
                             const std::string& scheme, double dt, const py::kwargs& kw) {
    auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(velocities);
    if (!v) type_error("velocities must be an array of numbers, shape (n, dim)");
    if (v.ndim() != 2)
      throw InvalidInput("velocities must have shape (n, dim), got " + std::to_string(v.ndim()) +
                         " dimensions");
    py::kwargs all = kw;
    all["n"] = py::int_(v.shape(0));
    all["dim"] = py::int_(v.shape(1));
    cli::RunOptions o = run_options(registry::EngineKind::dsmc, all,
                                    {"n", "dim", "model", "vhs_exponent", "seed", "threads",
                                     "mass_ratio"});
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
      if (!cli::two_species(o))
        throw InvalidInput("species needs mass_ratio != 1 (the mass of species 1)");
    } else if (cli::two_species(o)) {
      throw InvalidInput("mass_ratio needs species (which particles have that mass)");
    }
    // The time unit assumes the centre-of-mass frame (dsmc/time_unit.hpp).
    std::vector<long double> p(static_cast<std::size_t>(dim), 0.0L);
    long double mass = 0.0L, mv2 = 0.0L;
    for (std::size_t i = 0; i < n; ++i) {
      const double m = sp.empty() || sp[i] == 0 ? 1.0 : o.mass_ratio;
      mass += m;
      for (int k = 0; k < dim; ++k) {
        p[static_cast<std::size_t>(k)] += m * x[i * dim + k];
        mv2 += m * x[i * dim + k] * x[i * dim + k];
      }
    }
    long double p2 = 0.0L;
    for (long double pk : p) p2 += pk * pk;
    if (!(mv2 > 0.0L)) throw InvalidInput("velocities must not all be zero");
    if (std::sqrt(static_cast<double>(p2)) > 1e-9 * std::sqrt(static_cast<double>(mass * mv2)))
      throw InvalidInput("the total momentum must be zero (the time unit is defined in the "
                         "centre-of-mass frame): subtract the mass-weighted mean velocity");
    const GivenVelocities given{x, n, sp.empty() ? nullptr : sp.data()};
    return dsmc_box(make_dsmc(o, scheme, dt, &given), o.threads);
  }, py::arg("velocities"), py::arg("species") = py::none(), py::arg("scheme") = "exact",
        py::arg("dt") = 0.01);
  m.def("make_edmd", [](const py::kwargs& kw) {
    const cli::RunOptions o = run_options(registry::EngineKind::edmd, kw, edmd_keywords);
    auto box = std::make_unique<EngineBox>();
    {
      py::gil_scoped_release nogil;  // a dense start compresses for a while
      box->h = make_edmd(o);
    }
    return box;
  });
  m.def("set_threads", [dsmc](EngineBox& b, const py::object& t) {
    b.idle();
    const long long k = as_integer("threads", t);
    if (k < 1 || k > 64) throw InvalidInput("--threads must be in 1..64, got " + std::to_string(k));
    dsmc(b).set_threads(static_cast<int>(k));
  });
  m.def("threads", [dsmc](const EngineBox& b) { return dsmc(b).threads(); });
  m.def("candidates", [dsmc](const EngineBox& b) { return dsmc(b).candidates(); });
  m.def("model", [dsmc](const EngineBox& b) { return std::string(dsmc(b).model()); });
  m.def("positions", [edmd](py::object self) {
    EngineBox& b = self.cast<EngineBox&>();
    b.idle();
    return view(edmd(b).positions(), b.h->size(), b.h->dim(), self);
  });
  m.def("ids", [edmd](py::object self) {
    const EngineBox& b = self.cast<const EngineBox&>();
    return view_1d(edmd(b).ids(), b.h->size(), self);
  });
  m.def("unwrapped_positions", [edmd](const EngineBox& b) {
    b.idle();
    py::array_t<double> a(
        {static_cast<py::ssize_t>(b.h->size()), static_cast<py::ssize_t>(b.h->dim())});
    const auto x = edmd(b).unwrapped_positions();
    std::memcpy(a.mutable_data(), x.data(), x.size() * sizeof(double));
    return a;
  });
  m.def("edmd_observables", [edmd](const EngineBox& b) {
    b.idle();
    const EdmdHandle& e = edmd(b);
    py::dict d;
    d["box_side"] = e.box_side(), d["packing"] = e.packing(), d["temperature"] = e.temperature();
    d["pressure_Z"] = e.pressure_Z(), d["collision_rate"] = e.collision_rate();
    d["mean_free_time"] = e.mean_free_time();
    return d;
  });
  m.def("reset_observables", [edmd](EngineBox& b) {
    b.idle();
    edmd(b).reset_observables();
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

  // ---- the error-against-run-time study (studies/report.hpp)
  m.def("report", [](bool quick, const py::object& seed, const py::object& threads) {
    studies::ReportOptions o;
    o.quick = quick;
    o.seed = as_seed(seed);
    const long long t = as_integer("threads", threads);
    if (t < 1 || t > 64) throw InvalidInput("threads must be in 1..64, got " + std::to_string(t));
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
