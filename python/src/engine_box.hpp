// python/src/engine_box.hpp -- what the Python type Engine holds: an engine, the flag that
// lets one call at a time run it, and advance(), which runs it with the GIL released.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <memory>
#include <stdexcept>

#include "engine_handle.hpp"

namespace hypergas::python {

namespace py = pybind11;

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

/// Advances box's engine to t with the GIL released; every ~0.1 s of wall time it takes
/// the GIL back to let Python handle signals (Ctrl-C raises KeyboardInterrupt with the
/// engine consistent at the time reached) and to call `progress` (callable or None) with
/// the engine time. RuntimeError while another call runs the engine.
void advance(EngineBox& box, double t, const py::object& progress);

}  // namespace hypergas::python
