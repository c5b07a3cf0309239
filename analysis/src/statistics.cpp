// Distances (L1, KL) and goodness-of-fit tests (chi-square, KS) against a MB reference.
#include "hypergas/analysis/statistics.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>

#include "gsl_guard.hpp"
#include "hypergas/error.hpp"

namespace hypergas::analysis {

namespace {
// Bin fractions and reference probabilities, underflow first and overflow last.
struct BinPairs {
  std::vector<double> counts, probs;
  double total = 0.0;
};

BinPairs bin_pairs(const Histogram& h, const MaxwellReference& ref) {
  ref.validate();
  BinPairs b;
  b.total = h.total();
  if (!(b.total > 0.0)) throw InvalidInput("statistics: the histogram is empty");
  const std::size_t nb = h.bins();
  b.counts.reserve(nb + 2);
  b.probs.reserve(nb + 2);
  b.counts.push_back(h.underflow());
  b.probs.push_back(ref.cdf(h.lower(0)));
  for (std::size_t i = 0; i < nb; ++i) {
    b.counts.push_back(h.count(i));
    // Difference of CDFs, or of upper tails on the right side where the CDF saturates.
    const double lo = h.lower(i), hi = h.upper(i);
    const double p =
        ref.cdf(lo) < 0.5 ? ref.cdf(hi) - ref.cdf(lo) : ref.upper_tail(lo) - ref.upper_tail(hi);
    b.probs.push_back(std::max(p, 0.0));
  }
  b.counts.push_back(h.overflow());
  b.probs.push_back(ref.upper_tail(h.upper(nb - 1)));
  return b;
}
}  // namespace

double l1_distance(const Histogram& h, const MaxwellReference& ref) {
  const BinPairs b = bin_pairs(h, ref);
  double d = 0.0;
  for (std::size_t i = 0; i < b.counts.size(); ++i)
    d += std::abs(b.counts[i] / b.total - b.probs[i]);
  return d;
}

double kl_divergence(const Histogram& h, const MaxwellReference& ref) {
  const BinPairs b = bin_pairs(h, ref);
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
  const BinPairs b = bin_pairs(h, ref);
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

TestResult ks_test(std::vector<double> sample, const MaxwellReference& ref) {
  ref.validate();
  if (sample.empty()) throw InvalidInput("ks_test: empty sample");
  std::sort(sample.begin(), sample.end());
  const double n = static_cast<double>(sample.size());
  double d = 0.0;
  for (std::size_t i = 0; i < sample.size(); ++i) {
    const double f = ref.cdf(sample[i]);
    d = std::max({d, (i + 1) / n - f, f - i / n});
  }
  TestResult r;
  r.statistic = d;
  r.dof = n;
  const double sn = std::sqrt(n);
  r.p_value = kolmogorov_q((sn + 0.12 + 0.11 / sn) * d);  // Stephens (1970), JRSS B 32:115
  return r;
}

}  // namespace hypergas::analysis
