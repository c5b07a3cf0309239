// hypergas/analysis/statistics.hpp -- distances from Maxwell–Boltzmann and goodness-of-fit tests.
//
// All distances compare bin probabilities: the histogram's fractions p_i = count_i / total
// (underflow and overflow are two more bins) against the reference's exact bin
// probabilities P_i = cdf(hi_i) - cdf(lo_i). Both distances are biased upward by sampling
// noise: for N samples and B bins, E[L1] ~ sum_i sqrt(2 P_i / (pi N)) and E[KL] ~ (B-1)/(2N).
//
// The histogram statistics need O(bins) memory; the KS test needs its sample (sorted).
// SequentialSample draws a uniform subsample in one streaming pass, for a KS test of a
// sample too large to keep (see MomentsRecorder).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/rng.hpp"

namespace hypergas::analysis {

/// A test statistic with its degrees of freedom and p-value (probability, under the
/// reference, of a statistic at least this large).
struct TestResult {
  double statistic = 0.0;
  double dof = 0.0;  ///< degrees of freedom (chi-square), or sample size (KS)
  double p_value = 1.0;
};

/// A histogram's counts and the reference's probabilities of its bins, underflow first and
/// overflow last (bins() + 2 entries each): what the distances and the chi-square test
/// compare. The reference part depends on the bin edges only, so a caller that keeps its
/// edges computes it once (bin_probabilities) and sets the counts per snapshot.
struct BinnedCounts {
  std::vector<double> counts, probs;
  double total = 0.0;  ///< sum of the counts
};

/// The probabilities of h's bins under ref (differences of the CDF, or of upper tails on
/// the right side where the CDF saturates), underflow first, overflow last.
std::vector<double> reference_probabilities(const Histogram& h, const MaxwellReference& ref);
/// reference_probabilities with h's counts and total; throws InvalidInput if h is empty.
BinnedCounts bin_probabilities(const Histogram& h, const MaxwellReference& ref);

/// L1 distance sum_i |p_i - P_i| (dimensionless, 0..2; twice the total-variation distance).
double l1_distance(const Histogram& h, const MaxwellReference& ref);
double l1_distance(const BinnedCounts& b);

/// Kullback–Leibler divergence sum_i p_i ln(p_i / P_i) of the histogram from the reference
/// (nats, >= 0; bins with p_i = 0 contribute 0).
double kl_divergence(const Histogram& h, const MaxwellReference& ref);
double kl_divergence(const BinnedCounts& b);

/// Pearson chi-square test of the counts against N P_i. Neighbouring bins are merged until
/// each group expects >= 5 counts; dof = groups - 1 - fitted_parameters (use 1 when kT
/// came from the same sample). p from gsl_cdf_chisq_Q.
TestResult chi_square_test(const Histogram& h, const MaxwellReference& ref,
                           int fitted_parameters = 0);
TestResult chi_square_test(const BinnedCounts& b, int fitted_parameters = 0);
/// Whether chi_square_test(b, fitted_parameters) has a test: at least 2 + fitted_parameters
/// groups of >= 5 expected counts (it throws InvalidInput otherwise).
bool chi_square_possible(const BinnedCounts& b, int fitted_parameters = 0);

/// Two-sided one-sample Kolmogorov–Smirnov test of `sample` against ref.cdf: statistic
/// D_n = sup |F_n - F|, p from the asymptotic Kolmogorov distribution with Stephens' (1970)
/// finite-n correction (accurate to ~1% in p for n >= 35). With kT estimated from the same
/// sample the test is conservative (p too large; Lilliefors 1967). The sample is taken by
/// value and sorted: pass it with std::move where the caller no longer needs it, to avoid
/// a copy.
TestResult ks_test(std::vector<double> sample, const MaxwellReference& ref);

/// The KS test of n values known only by the fine bins they fall in: `counts` holds
/// `bins` + 2 counts (underflow, bins 0 .. bins - 1, overflow) and `cdf` the reference CDF
/// at the bins + 1 edges. The statistic is max |F_n - F| over the edges, where F_n is
/// known exactly; it is at most the exact D_n of the values and at least D_n minus the
/// largest reference probability of one bin, so the p-value (as ks_test's, for n values)
/// is conservative: it rejects a true reference at most as often as the exact test.
TestResult ks_test_binned(const std::int64_t* counts, const double* cdf, std::size_t bins);

/// The KS p-value of statistic d for n values (Stephens' finite-n form, as ks_test).
double ks_p_value(double d, double n);

/// Selection sampling (Knuth, TAOCP vol. 2, sec. 3.4.2, Algorithm S): visits the indices
/// 0 .. n-1 in increasing order and takes each with probability (still needed) / (still
/// left), which takes exactly min(k, n) of them, every subset of that size with the same
/// probability (a uniform sample without replacement). O(1) memory; one unbiased random
/// integer (Rng::below) per index visited while 0 < needed < left, none when k >= n.
class SequentialSample {
 public:
  /// k of n indices, random integers from `rng`.
  SequentialSample(std::uint64_t n, std::uint64_t k, Rng rng)
      : left_(n), needed_(k < n ? k : n), rng_(rng) {}

  /// Whether the next index is taken. Call it once per index, in order, n times at most
  /// (after n calls it returns false).
  bool take() {
    if (left_ == 0) return false;
    const bool t = needed_ >= left_ || (needed_ > 0 && rng_.below(left_) < needed_);
    --left_;
    needed_ -= t;
    return t;
  }

 private:
  std::uint64_t left_;    // indices not yet visited
  std::uint64_t needed_;  // indices still to take
  Rng rng_;
};

/// Kolmogorov distribution upper tail Q(lambda) = 2 sum_k (-1)^(k-1) exp(-2 k^2 lambda^2).
double kolmogorov_q(double lambda);

}  // namespace hypergas::analysis
