// python/src/arrays.cpp -- numpy arrays to and from the engines and the analysis code
// (arrays.hpp).
#include "arrays.hpp"

#include <cmath>
#include <string>

#include "hypergas/error.hpp"

namespace hypergas::python {

py::array view(const Rows& rows, std::size_t n, int cols, py::handle base) {
  py::array a(py::dtype::of<double>(), {n, static_cast<std::size_t>(cols)},
              {static_cast<py::ssize_t>(rows.stride * sizeof(double)),
               static_cast<py::ssize_t>(sizeof(double))},
              rows.data, base);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

py::array_t<double> to_numpy(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

void check_finite_rows(const double* x, std::size_t rows, int cols, std::size_t stride) {
  for (std::size_t i = 0; i < rows; ++i)
    for (int k = 0; k < cols; ++k)
      if (!std::isfinite(x[i * stride + static_cast<std::size_t>(k)]))
        throw InvalidInput("velocities must be finite (particle " + std::to_string(i) + ")");
}

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

}  // namespace hypergas::python
