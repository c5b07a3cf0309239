// sim/outputs/route_check.hpp -- one coefficient by two routes, held against each other in
// every run that has both: the summary key `<name>_route_difference_se`, their difference
// over the combined standard error sqrt(se_a^2 + se_b^2), and one stderr line when it
// exceeds route_alarm. The two routes of one run share the trajectory, so their errors are
// positively correlated and the combined error overstates the difference's: the check is
// conservative (a difference above 3 is then a defect, not chance).
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/transport_recorder.hpp"

namespace hypergas::cli {

/// Differences in combined standard errors above this are said on stderr.
inline constexpr double route_alarm = 3.0;

/// (a - b) / sqrt(ea^2 + eb^2); NaN where that is undefined.
inline double route_difference(double a, double ea, double b, double eb) {
  const double se = std::hypot(ea, eb);
  return std::isfinite(a) && std::isfinite(b) && se > 0.0
             ? (a - b) / se
             : std::numeric_limits<double>::quiet_NaN();
}

/// Adds `key` = the difference of routes a and b in combined standard errors, and says it
/// on stderr when it exceeds route_alarm (`what`: the routes, in words).
inline void check_routes(analysis::JsonObject& s, const std::string& key, double a, double ea,
                         double b, double eb, const std::string& what) {
  const double z = route_difference(a, ea, b, eb);
  s.emplace_back(key, z);
  if (std::isfinite(z) && std::fabs(z) > route_alarm)
    fmt::print(stderr,
               "hypergas: warning: {}: {:.5g} +- {:.2g} against {:.5g} +- {:.2g}, {:.1f} "
               "combined standard errors apart\n",
               what, a, ea, b, eb, z);
}

/// check_routes for two rows of transport.csv: key `<a>_route_difference_se`.
inline void check_rows(analysis::JsonObject& s,
                       const std::vector<analysis::TransportCoefficient>& rows,
                       const std::string& a, const std::string& b) {
  const analysis::TransportCoefficient *x = nullptr, *y = nullptr;
  for (const auto& r : rows) {
    if (r.name == a) x = &r;
    if (r.name == b) y = &r;
  }
  if (!x || !y) return;
  check_routes(s, a + "_route_difference_se", x->value, x->error, y->value, y->error,
               a + " by " + a + " and by " + b);
}

}  // namespace hypergas::cli
