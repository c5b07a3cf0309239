// studies/src/clock.hpp -- the clocks the studies time with.
//
// The project's machines are shared: wall time includes time the thread waited for a core
// (and, in a virtual machine, time the host gave to others). CPU seconds of the thread
// exclude that waiting; they do not exclude slower memory while other tenants load it.
#pragma once

#include <time.h>

#include <chrono>

namespace hypergas::studies::detail {

/// CPU seconds used by the calling thread (CLOCK_THREAD_CPUTIME_ID).
inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// Wall or thread-CPU seconds since construction.
class Stopwatch {
 public:
  explicit Stopwatch(bool cpu = false)
      : cpu_(cpu),
        wall0_(std::chrono::steady_clock::now()),
        cpu0_(cpu ? thread_cpu_seconds() : 0.0) {}
  double seconds() const {
    if (cpu_) return thread_cpu_seconds() - cpu0_;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
  }

 private:
  bool cpu_;
  std::chrono::steady_clock::time_point wall0_;
  double cpu0_;
};

}  // namespace hypergas::studies::detail
