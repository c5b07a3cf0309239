// python/src/engine_box.cpp -- advance(): an engine run with the GIL released, polled for
// signals and progress (engine_box.hpp).
#include "engine_box.hpp"

#include <chrono>
#include <functional>

namespace hypergas::python {
namespace {

/// A Python exception raised inside a poll, carried through the engine as a C++ exception
/// and restored once the GIL is held again.
struct PythonStop {};

}  // namespace

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

}  // namespace hypergas::python
