// hypergas/analysis/histogram.hpp -- a counting histogram (GSL's gsl_histogram inside).
//
// Equal-width bins on [lo, hi); values below lo or at/above hi are counted as underflow and
// overflow, so that densities and distances are normalised by every value added. Values are
// added one at a time, so a histogram of N values needs O(bins) memory, not O(N).
//
// Checkpoints: io() saves and restores the exact state (bin edges, counts, underflow,
// overflow) through a checkpoint archive (hypergas/checkpoint.hpp).
#pragma once

#include <limits>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "hypergas/analysis/maxwell.hpp"

namespace hypergas::analysis {

class Histogram {
 public:
  /// `bins` equal bins on [lo, hi) (units of the quantity). Throws InvalidInput unless
  /// lo < hi are finite and bins >= 1.
  Histogram(double lo, double hi, std::size_t bins);
  /// One empty bin on [0, 1): a placeholder for containers, to be assigned or restored.
  Histogram();
  ~Histogram();
  Histogram(const Histogram& other);
  Histogram& operator=(const Histogram& other);
  Histogram(Histogram&&) noexcept;
  Histogram& operator=(Histogram&&) noexcept;

  /// Counts x once. Throws InvalidInput for a non-finite x.
  void add(double x);
  /// Counts every value of xs.
  void add(const std::vector<double>& xs);
  /// Adds the counts of `o`, which must have the same bins (throws InvalidInput otherwise).
  void merge(const Histogram& o);
  /// Replaces the counts (bins() of them), underflow and overflow, keeping the edges: for
  /// counts made elsewhere (a tally's fine bins). Throws InvalidInput for a wrong number
  /// of counts or a count that is not a whole number >= 0.
  void set_counts(const std::vector<double>& counts, double under, double over);

  std::size_t bins() const;
  double lower(std::size_t i) const;  ///< lower edge of bin i (units of x)
  double upper(std::size_t i) const;  ///< upper edge of bin i (units of x)
  double count(std::size_t i) const;  ///< values in bin i
  double underflow() const;           ///< values below lower(0)
  double overflow() const;            ///< values at or above upper(bins()-1)
  double total() const;               ///< all values added, in range or not
  /// count(i) / (total() * width): the estimated density (1 / units of x); 0 if empty.
  double density(std::size_t i) const;

  /// Saves (checkpoint::Writer) or restores (checkpoint::Reader) the whole state: the bins()
  /// + 1 edges as they are (not recomputed from lo and hi), the counts, underflow and
  /// overflow. Restoring throws InvalidInput for an inconsistent state and then leaves
  /// this histogram unchanged.
  template <class Archive>
  void io(Archive& a) {
    a.tag("histogram");
    std::vector<double> edges, counts;
    double under = 0.0, over = 0.0;
    if constexpr (Archive::saving) {
      for (std::size_t i = 0; i < bins(); ++i) {
        edges.push_back(lower(i));
        counts.push_back(count(i));
      }
      edges.push_back(upper(bins() - 1));
      under = underflow();
      over = overflow();
    }
    a(edges, counts, under, over);
    if constexpr (!Archive::saving) restore(edges, counts, under, over);
  }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  // Replaces the state by the given one (the inverse of what io() saves).
  void restore(const std::vector<double>& edges, const std::vector<double>& counts, double under,
               double over);
};

/// An empty histogram whose range covers `ref` up to tail probability 1e-7 on each open
/// side (speed and energy start at 0), to be filled one value at a time.
Histogram make_histogram(const MaxwellReference& ref, std::size_t bins = 50);

/// make_histogram(ref, bins) filled with `xs`.
Histogram make_histogram(const std::vector<double>& xs, const MaxwellReference& ref,
                         std::size_t bins = 50);

/// The reference's mean density over [lo, hi) (1 / units of x): the bin's exact
/// probability over its width.
double bin_density(const MaxwellReference& ref, double lo, double hi);

/// Writes `h` as CSV `lo,hi,count,density,maxwell_density` (atomically): bin edges (units
/// of x), counts, the histogram density and the reference's mean density over each bin
/// (both 1 / units of x).
/// With a finite `a2` and a speed reference, also the column sonine_density: the bin
/// average of the first Sonine form pdf(v) (1 + a2 S2(c^2)), c^2 = m v^2 / (2 kT),
/// S2(x) = x^2/2 - (D+2) x/2 + D(D+2)/8 (granular/theory.hpp).
void write_histogram_csv(const std::string& path, const Histogram& h, const MaxwellReference& ref,
                         double a2 = std::numeric_limits<double>::quiet_NaN());
/// The bin average over [lo, hi] of the first Sonine speed density with coefficient a2.
double sonine_bin_density(const MaxwellReference& ref, double a2, double lo, double hi);

}  // namespace hypergas::analysis
