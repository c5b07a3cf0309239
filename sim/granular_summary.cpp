// sim/granular_summary.cpp -- the summary keys of a granular run (granular_summary.hpp).
#include "granular_summary.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <string>
#include <vector>

#include "hypergas/analysis/estimates.hpp"
#include "hypergas/analysis/fit.hpp"
#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/granular/theory.hpp"

namespace hypergas::cli {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t blocks = 8;

/// Mean and standard error over `blocks` consecutive blocks of rows [b, e) of f(block b, e).
template <class F>
analysis::MeanSe over_blocks(std::size_t b, std::size_t e, F f) {
  return analysis::over_blocks(b, e, blocks, f);
}

/// Slope A of ln(f / c^(D-1)) = b - A c over the bins of the last speed histogram with
/// c = v / v_T >= 2 and at least 20 counts (weighted by the counts), for the measured
/// density and for the Maxwellian of the same bins; NaN without 3 such bins.
std::pair<double, double> tail_slopes(const analysis::MomentsRecorder& m, int d) {
  const analysis::Histogram& h = m.last_histogram();
  const analysis::MaxwellReference& ref = m.last_reference();
  const double vt = std::sqrt(2.0 * ref.kT / ref.mass);
  std::vector<double> c, y, ym, w;
  for (std::size_t i = 0; i < h.bins(); ++i) {
    const double lo = h.lower(i) / vt, hi = h.upper(i) / vt, mid = 0.5 * (lo + hi);
    if (lo < 2.0 || h.count(i) < 20.0) continue;
    c.push_back(mid);
    y.push_back(std::log(h.density(i)) - (d - 1) * std::log(mid));
    ym.push_back(std::log(analysis::bin_density(ref, h.lower(i), h.upper(i))) -
                 (d - 1) * std::log(mid));
    w.push_back(h.count(i));
  }
  if (c.size() < 3) return {nan, nan};
  return {-analysis::line_slope(c, y, 0, c.size(), w),
          -analysis::line_slope(c, ym, 0, c.size(), w)};
}

}  // namespace

void add_granular_summary(analysis::JsonObject& summary, const analysis::MomentsRecorder& m,
                          const GranularRun& run, bool dsmc_time_unit) {
  const std::vector<double> a2 = m.column("a2"), a3 = m.column("a3"), T = m.column("T"),
                            t = m.column("real_time"), cpp = m.column("collisions_per_particle");
  const std::size_t n = T.size();
  const double alpha = run.restitution;
  const int d = run.dim;
  const auto put = [&](const std::string& k, double v) { summary.emplace_back(k, v); };
  put("restitution", alpha);
  put("temperature_ratio", n > 0 ? T.back() / T.front() : nan);
  const bool enough = n >= 2 * blocks && d >= 2;
  const std::size_t b = n / 2;
  const auto mean_of = [&](const std::vector<double>& y) {
    return analysis::block_average(y, b, n, blocks);
  };
  const analysis::MeanSe a2m = enough ? mean_of(a2) : analysis::MeanSe{nan, nan};
  const analysis::MeanSe a3m = enough ? mean_of(a3) : analysis::MeanSe{nan, nan};
  put("a2_mean", a2m.mean);
  put("a2_error", a2m.se);
  put("a3_mean", a3m.mean);
  put("a3_error", a3m.se);
  const double a2s = !run.hard_spheres || d < 2 ? nan
                     : run.driven               ? granular::a2_white_noise(alpha, d)
                                                : granular::a2_hcs(alpha, d);
  put("a2_sonine", a2s);
  std::vector<double> lnT;
  for (const double x : T) lnT.push_back(std::log(x));
  const analysis::MeanSe cool =
      enough && !run.driven ? over_blocks(b, n, [&](std::size_t i, std::size_t e) {
        return -analysis::line_slope(cpp, lnT, i, e);
      })
                            : analysis::MeanSe{nan, nan};
  put("cooling_per_collision", cool.mean);
  put("cooling_per_collision_error", cool.se);
  put("cooling_per_collision_sonine",
      run.hard_spheres && d >= 2 && !run.driven
          ? granular::cooling_rate(alpha, d, a2s) / granular::collision_frequency_ratio(a2s)
          : nan);
  const auto [tail, tail_mb] = n > 0 ? tail_slopes(m, d) : std::pair<double, double>{nan, nan};
  put("tail_slope", tail);
  put("tail_slope_maxwell", tail_mb);
  if (!run.driven) {
    std::vector<double> inv;
    for (const double x : T) inv.push_back(1.0 / std::sqrt(x));
    const analysis::MeanSe haff =
        enough ? over_blocks(b, n, [&](std::size_t i, std::size_t e) {
          return 1.0 / (std::sqrt(T.front()) * analysis::line_slope(t, inv, i, e));
        })
               : analysis::MeanSe{nan, nan};
    put("haff_t0", haff.mean);
    put("haff_t0_error", haff.se);
    put("haff_t0_sonine", dsmc_time_unit && run.hard_spheres && d >= 2
                              ? 2.0 / granular::cooling_rate(alpha, d, a2s)
                              : nan);
  } else {
    const analysis::MeanSe r = over_blocks(b, n, [&](std::size_t i, std::size_t e) {
      return analysis::range_mean(T, i, e) / T.front();
    });
    put("temperature_ratio_mean", enough ? r.mean : nan);
    put("temperature_ratio_error", enough ? r.se : nan);
  }
}

}  // namespace hypergas::cli
