// hypergas/schedule.hpp -- the sampling instants of a run: one rule for both engines'
// run_until, the command's run loop and Python's run.
//
// The rule: a run from t0 to `until` with a requested interval `every` samples K + 1 evenly
// spaced instants t_k = t0 + k (until - t0) / K, k = 0..K, where K = max(1, round((until -
// t0) / every)). So `every` is rounded to the nearest interval that divides the span, the
// rows are evenly spaced (what the VACF and any correlation of the rows need) and the last
// row is at `until` exactly. Without a requested interval K = 50. A span of zero samples
// t0 once.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "hypergas/error.hpp"

namespace hypergas {

class Schedule {
 public:
  /// Intervals when `every` is not given: 50, so 51 rows.
  static constexpr std::uint64_t default_intervals = 50;
  /// Most intervals a run may ask for (each is a row of moments.csv).
  static constexpr double max_intervals = 1e6;

  /// The schedule from t0 to until with requested interval `every` (<= 0: not given).
  /// Throws InvalidInput if the times are not finite, until < t0, every is NaN or infinite,
  /// or the span holds more than max_intervals intervals.
  static Schedule make(double t0, double until, double every = 0.0) {
    if (!std::isfinite(t0) || !std::isfinite(until))
      throw InvalidInput("sampling: the start and end times must be finite");
    if (until < t0)
      throw InvalidInput("sampling: the end time " + num(until) + " is before the start " +
                         num(t0));
    if (std::isnan(every) || std::isinf(every))
      throw InvalidInput("sampling: the interval must be finite, got " + num(every));
    Schedule s;
    s.t0_ = t0;
    s.until_ = until;
    const double span = until - t0;
    if (!(span > 0.0)) return s;  // one row, at t0
    if (every > 0.0) {
      const double k = std::round(span / every);
      if (k > max_intervals)
        throw InvalidInput("sampling: (until - t0) / every = " + num(span / every) +
                           " samples; at most 1e6");
      s.k_ = static_cast<std::uint64_t>(std::max(1.0, k));
    } else {
      s.k_ = default_intervals;
    }
    s.every_ = span / static_cast<double>(s.k_);
    return s;
  }

  /// Instant k in 0..intervals(): t0 + k every, and `until` exactly for the last.
  double time(std::uint64_t k) const {
    return k >= k_ ? until_ : t0_ + static_cast<double>(k) * every_;
  }
  /// Number of intervals K (0 for a zero span); rows() = K + 1.
  std::uint64_t intervals() const { return k_; }
  std::uint64_t rows() const { return k_ + 1; }
  /// The interval used, (until - t0) / K (0 for a zero span).
  double every() const { return every_; }
  double t0() const { return t0_; }
  double until() const { return until_; }

 private:
  static std::string num(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
  }
  double t0_ = 0.0, until_ = 0.0, every_ = 0.0;
  std::uint64_t k_ = 0;
};

}  // namespace hypergas
