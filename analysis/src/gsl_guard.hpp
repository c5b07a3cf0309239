// Private: GSL's default error handler aborts the program. Inside the analysis library GSL
// errors are reported through return codes (checked by the caller) instead.
#pragma once

#include <gsl/gsl_errno.h>

namespace hypergas::analysis::detail {

/// Turns GSL's abort-on-error handler off for its lifetime and restores the previous one.
/// (GSL's handler is process-global; the analysis is called from one thread at a time.)
class GslErrorGuard {
 public:
  GslErrorGuard() : previous_(gsl_set_error_handler_off()) {}
  ~GslErrorGuard() { gsl_set_error_handler(previous_); }
  GslErrorGuard(const GslErrorGuard&) = delete;
  GslErrorGuard& operator=(const GslErrorGuard&) = delete;

 private:
  gsl_error_handler_t* previous_;
};

}  // namespace hypergas::analysis::detail
