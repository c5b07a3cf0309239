// analysis/src/fftw_planner.hpp -- the one lock around FFTW's planner (not thread-safe:
// plans are made and destroyed under it; executing a plan needs no lock).
#pragma once

#include <mutex>

namespace hypergas::analysis::detail {

inline std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace hypergas::analysis::detail
