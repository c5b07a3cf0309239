// Private: GSL's default error handler aborts the program. Inside the analysis library GSL
// errors are reported through return codes (checked by the caller) instead.
#pragma once

#include <gsl/gsl_errno.h>

#include <mutex>

namespace hypergas::analysis::detail {

/// Turns GSL's abort-on-error handler off while at least one guard lives (in any thread)
/// and restores the caller's handler when the last one ends. GSL's handler is process-wide,
/// so the guards share one count under a mutex.
class GslErrorGuard {
 public:
  GslErrorGuard() {
    std::lock_guard lock(mutex());
    if (count()++ == 0) previous() = gsl_set_error_handler_off();
  }
  ~GslErrorGuard() {
    std::lock_guard lock(mutex());
    if (--count() == 0) gsl_set_error_handler(previous());
  }
  GslErrorGuard(const GslErrorGuard&) = delete;
  GslErrorGuard& operator=(const GslErrorGuard&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static int& count() {
    static int c = 0;
    return c;
  }
  static gsl_error_handler_t*& previous() {
    static gsl_error_handler_t* p = nullptr;
    return p;
  }
};

}  // namespace hypergas::analysis::detail
