// python/src/arrays.hpp -- numpy arrays to and from the engines and the analysis code:
// read-only views of engine memory, copies, snapshots of velocity arrays and series.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <vector>

#include "convert.hpp"
#include "engine_handle.hpp"
#include "hypergas/observer.hpp"

namespace hypergas::python {

/// A read-only numpy view of `rows` (n x cols doubles, `stride` doubles apart), owned by
/// `base`.
py::array view(const Rows& rows, std::size_t n, int cols, py::handle base);

/// A read-only numpy view of n values at `data`, owned by `base`.
template <class T>
py::array view_1d(const T* data, std::size_t n, py::handle base) {
  py::array a(py::dtype::of<T>(), {n}, {static_cast<py::ssize_t>(sizeof(T))}, data, base);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

/// A new float64 array holding a copy of v.
py::array_t<double> to_numpy(const std::vector<double>& v);

/// Throws InvalidInput naming the particle unless rows x 0..cols-1 (`stride` apart) are
/// finite.
void check_finite_rows(const double* x, std::size_t rows, int cols, std::size_t stride);

/// A snapshot of a numpy array of velocities (n x D, float64, rows `stride` doubles apart,
/// components contiguous; anything else is copied into that form) and optional masses.
struct ArraySnapshot {
  py::array_t<double> v;  // keeps the data alive
  std::vector<double> inv_mass;
  Snapshot s;
};

/// The snapshot of `velocities` (and `masses`, or None) at `time`; InvalidInput or
/// TypeError for arrays of the wrong shape, type or values.
ArraySnapshot array_snapshot(const py::handle& velocities, const py::handle& masses, double time);

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
std::vector<double> series(const py::handle& x, std::size_t& frames, std::size_t& n, int& dim);

/// The max_lag argument (None: frames / 2), checked to be in 0..frames-1.
std::size_t max_lag_of(const py::object& max_lag, std::size_t frames);

}  // namespace hypergas::python
