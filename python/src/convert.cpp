// python/src/convert.cpp -- Python values as C++ arguments (convert.hpp) and the Python
// spelling of the command's messages.
#include "convert.hpp"

#include <cmath>

#include "hypergas/error.hpp"

namespace hypergas::python {

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

void type_error(const std::string& msg) { throw py::type_error(msg); }

std::string type_name(const py::handle& h) { return py::str(py::type::handle_of(h).attr("__name__")); }

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

}  // namespace hypergas::python
