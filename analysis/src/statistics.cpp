// Distances (L1, KL) and goodness-of-fit tests (chi-square, KS) against a MB reference.
#include "hypergas/analysis/statistics.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>
#include <utility>

#include "gsl_guard.hpp"
#include "hypergas/error.hpp"

namespace hypergas::analysis {

std::vector<double> reference_probabilities(const Histogram& h, const MaxwellReference& ref) {
  ref.validate();
  const std::size_t nb = h.bins();
  std::vector<double> probs;
  probs.reserve(nb + 2);
  probs.push_back(ref.cdf(h.lower(0)));
  for (std::size_t i = 0; i < nb; ++i) {
    // Difference of CDFs, or of upper tails on the right side where the CDF saturates.
    const double lo = h.lower(i), hi = h.upper(i);
    const double p =
        ref.cdf(lo) < 0.5 ? ref.cdf(hi) - ref.cdf(lo) : ref.upper_tail(lo) - ref.upper_tail(hi);
    probs.push_back(std::max(p, 0.0));
  }
  probs.push_back(ref.upper_tail(h.upper(nb - 1)));
  return probs;
}

BinnedCounts bin_probabilities(const Histogram& h, const MaxwellReference& ref) {
  BinnedCounts b;
  b.probs = reference_probabilities(h, ref);
  b.total = h.total();
  if (!(b.total > 0.0)) throw InvalidInput("statistics: the histogram is empty");
  b.counts.reserve(h.bins() + 2);
  b.counts.push_back(h.underflow());
  for (std::size_t i = 0; i < h.bins(); ++i) b.counts.push_back(h.count(i));
  b.counts.push_back(h.overflow());
  return b;
}

namespace {
void check_binned(const BinnedCounts& b) {
  if (!(b.total > 0.0)) throw InvalidInput("statistics: the histogram is empty");
  if (b.counts.size() != b.probs.size() || b.counts.size() < 3)
    throw InvalidInput("statistics: counts and bin probabilities differ in number");
}
}  // namespace

double l1_distance(const Histogram& h, const MaxwellReference& ref) {
  return l1_distance(bin_probabilities(h, ref));
}

double l1_distance(const BinnedCounts& b) {
  check_binned(b);
  double d = 0.0;
  for (std::size_t i = 0; i < b.counts.size(); ++i)
    d += std::abs(b.counts[i] / b.total - b.probs[i]);
  return d;
}

double kl_divergence(const Histogram& h, const MaxwellReference& ref) {
  return kl_divergence(bin_probabilities(h, ref));
}

double kl_divergence(const BinnedCounts& b) {
  check_binned(b);
  double d = 0.0;
  for (std::size_t i = 0; i < b.counts.size(); ++i) {
    if (b.counts[i] <= 0.0) continue;
    const double p = b.counts[i] / b.total;
    if (b.probs[i] <= 0.0) return HUGE_VAL;  // mass where the reference has none
    d += p * std::log(p / b.probs[i]);
  }
  return std::max(d, 0.0);
}

TestResult chi_square_test(const Histogram& h, const MaxwellReference& ref, int fitted_parameters) {
  return chi_square_test(bin_probabilities(h, ref), fitted_parameters);
}

namespace {
/// The counts and expectations of b's bins merged left to right until each group expects
/// >= 5 counts (the remainder joins the last group).
std::pair<std::vector<double>, std::vector<double>> chi_square_groups(const BinnedCounts& b) {
  check_binned(b);
  constexpr double min_expected = 5.0;
  std::vector<double> obs, expct;
  double o = 0.0, e = 0.0;
  for (std::size_t i = 0; i < b.counts.size(); ++i) {
    o += b.counts[i];
    e += b.total * b.probs[i];
    if (e >= min_expected) {
      obs.push_back(o);
      expct.push_back(e);
      o = e = 0.0;
    }
  }
  if (!obs.empty()) {  // the remainder joins the last group
    obs.back() += o;
    expct.back() += e;
  } else {
    obs.push_back(o);
    expct.push_back(e);
  }
  return {std::move(obs), std::move(expct)};
}
}  // namespace

bool chi_square_possible(const BinnedCounts& b, int fitted_parameters) {
  const double groups = static_cast<double>(chi_square_groups(b).first.size());
  return groups - 1.0 - fitted_parameters >= 1.0;
}

TestResult chi_square_test(const BinnedCounts& b, int fitted_parameters) {
  const auto [obs, expct] = chi_square_groups(b);
  TestResult r;
  r.dof = static_cast<double>(obs.size()) - 1.0 - fitted_parameters;
  if (r.dof < 1.0)
    throw InvalidInput("chi_square_test: too few counts for a test (need >= 5 expected in " +
                       std::to_string(2 + fitted_parameters) + " groups)");
  for (std::size_t g = 0; g < obs.size(); ++g) {
    const double d = obs[g] - expct[g];
    r.statistic += d * d / expct[g];
  }
  detail::GslErrorGuard guard;
  r.p_value = gsl_cdf_chisq_Q(r.statistic, r.dof);
  return r;
}

double kolmogorov_q(double lambda) {
  if (lambda < 0.2) return 1.0;  // Q(0.2) = 1 - 1e-10
  double q = 0.0;
  for (int k = 1; k <= 100; ++k) {
    const double term = std::exp(-2.0 * k * k * lambda * lambda);
    q += (k % 2 ? 2.0 : -2.0) * term;
    if (term < 1e-300) break;
  }
  return std::clamp(q, 0.0, 1.0);
}

namespace {

/// The KS statistic sup |F_n - F| of a sorted sample, with the exact CDF at every point.
double ks_statistic_sorted(const std::vector<double>& x, const MaxwellReference& ref) {
  const double n = static_cast<double>(x.size());
  double d = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = ref.cdf(x[i]);
    d = std::max({d, (i + 1) / n - f, f - i / n});
  }
  return d;
}

/// Piecewise-linear interpolant of the reference CDF on [lo, hi] with a bound on its error:
/// monotone (linear pieces between exact, non-decreasing values), so it orders values as
/// the CDF does; `error` is 4x the largest error found at the interval midpoints plus
/// 1e-15 (the error of linear interpolation of a smooth function peaks near the midpoint).
struct CdfTable {
  double lo = 0.0, inv_h = 0.0, error = 0.0;
  std::vector<double> f;
  CdfTable(const MaxwellReference& ref, double lo_, double hi, std::size_t pieces)
      : lo(lo_), f(pieces + 1) {
    const double h = (hi - lo) / static_cast<double>(pieces);
    inv_h = 1.0 / h;
    for (std::size_t k = 0; k <= pieces; ++k)
      f[k] = ref.cdf(k == pieces ? hi : lo + h * static_cast<double>(k));
    double worst = 0.0;
    for (std::size_t k = 0; k < pieces; ++k) {
      const double mid = lo + h * (static_cast<double>(k) + 0.5);
      worst = std::max(worst, std::fabs(ref.cdf(mid) - (*this)(mid)));
    }
    error = 4.0 * worst + 1e-15;
  }
  double operator()(double x) const {
    const double t = std::max(0.0, (x - lo) * inv_h);
    const auto k = std::min(static_cast<std::size_t>(t), f.size() - 2);
    const double w = std::min(t - static_cast<double>(k), 1.0);
    return f[k] + w * (f[k + 1] - f[k]);
  }
};

}  // namespace

// The sample is ordered by a counting sort on the interpolated CDF value (n buckets of
// width 1/n: about one value per bucket under the null hypothesis) and each bucket by
// value, in O(n) expected time; the statistic is found with the interpolant and then
// recomputed with the exact CDF at every point whose deviation could reach the maximum
// (within twice the interpolant's error bound of it). The result is that of sorting and
// evaluating the exact CDF everywhere, bit for bit (tests/unit/test_analysis_statistics).
TestResult ks_test(std::vector<double> sample, const MaxwellReference& ref) {
  ref.validate();
  if (sample.empty()) throw InvalidInput("ks_test: empty sample");
  const std::size_t n = sample.size();
  double d = 0.0;
  const auto [lo_it, hi_it] = std::minmax_element(sample.begin(), sample.end());
  const double lo = *lo_it, hi = *hi_it;
  if (n < 4096 || !(hi > lo) || !std::isfinite(hi - lo)) {
    std::sort(sample.begin(), sample.end());
    d = ks_statistic_sorted(sample, ref);
  } else {
    const CdfTable cdf(ref, lo, hi, 1u << 16);
    // counting sort by bucket floor(n F~(x)); F~ is monotone, so buckets follow x
    std::vector<std::uint32_t> bucket(n), start(n + 1, 0);
    const double dn = static_cast<double>(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto b = std::min(static_cast<std::size_t>(dn * cdf(sample[i])), n - 1);
      bucket[i] = static_cast<std::uint32_t>(b);
      ++start[b + 1];
    }
    for (std::size_t b = 0; b < n; ++b) start[b + 1] += start[b];
    std::vector<double> sorted(n);
    {
      std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
      for (std::size_t i = 0; i < n; ++i) sorted[next[bucket[i]]++] = sample[i];
    }
    for (std::size_t b = 0; b < n; ++b)
      if (start[b + 1] - start[b] > 1)
        std::sort(sorted.begin() + start[b], sorted.begin() + start[b + 1]);
    // the statistic with the interpolant, then the exact CDF where it can matter
    double approx = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double f = cdf(sorted[i]);
      approx = std::max({approx, (i + 1) / dn - f, f - i / dn});
    }
    const double floor = approx - 2.0 * cdf.error;
    for (std::size_t i = 0; i < n; ++i) {
      const double fa = cdf(sorted[i]);
      if (std::max((i + 1) / dn - fa, fa - i / dn) < floor) continue;
      const double f = ref.cdf(sorted[i]);
      d = std::max({d, (i + 1) / dn - f, f - i / dn});
    }
  }
  TestResult r;
  r.statistic = d;
  r.dof = static_cast<double>(n);
  r.p_value = ks_p_value(d, r.dof);
  return r;
}

double ks_p_value(double d, double n) {
  const double sn = std::sqrt(n);
  return kolmogorov_q((sn + 0.12 + 0.11 / sn) * d);  // Stephens (1970), JRSS B 32:115
}

TestResult ks_test_binned(const std::int64_t* counts, const double* cdf, std::size_t bins) {
  std::int64_t n = 0;
  for (std::size_t b = 0; b < bins + 2; ++b) {
    if (counts[b] < 0) throw InvalidInput("ks_test_binned: a negative count");
    n += counts[b];
  }
  if (n <= 0) throw InvalidInput("ks_test_binned: no values");
  const double dn = static_cast<double>(n);
  // F_n at edge k is the count below it: the underflow and bins 0 .. k-1
  std::int64_t below = counts[0];
  double d = std::abs(static_cast<double>(below) / dn - cdf[0]);
  for (std::size_t k = 1; k <= bins; ++k) {
    below += counts[k];
    d = std::max(d, std::abs(static_cast<double>(below) / dn - cdf[k]));
  }
  TestResult r;
  r.statistic = d;
  r.dof = dn;
  r.p_value = ks_p_value(d, dn);
  return r;
}

}  // namespace hypergas::analysis
