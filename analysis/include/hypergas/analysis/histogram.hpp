// hypergas/analysis/histogram.hpp -- a counting histogram (GSL's gsl_histogram inside).
//
// Equal-width bins on [lo, hi); values below lo or at/above hi are counted as underflow and
// overflow, so that densities and distances are normalised by every value added.
#pragma once

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
  ~Histogram();
  Histogram(const Histogram& other);
  Histogram& operator=(const Histogram& other);
  Histogram(Histogram&&) noexcept;
  Histogram& operator=(Histogram&&) noexcept;

  /// Counts x once. Throws InvalidInput for a non-finite x.
  void add(double x);
  /// Counts every value of xs.
  void add(const std::vector<double>& xs);

  std::size_t bins() const;
  double lower(std::size_t i) const;  ///< lower edge of bin i (units of x)
  double upper(std::size_t i) const;  ///< upper edge of bin i (units of x)
  double count(std::size_t i) const;  ///< values in bin i
  double underflow() const;           ///< values below lower(0)
  double overflow() const;            ///< values at or above upper(bins()-1)
  double total() const;               ///< all values added, in range or not
  /// count(i) / (total() * width): the estimated density (1 / units of x); 0 if empty.
  double density(std::size_t i) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A histogram whose range covers `ref` up to tail probability 1e-7 on each open side
/// (speed and energy start at 0), filled with `xs`.
Histogram make_histogram(const std::vector<double>& xs, const MaxwellReference& ref,
                         std::size_t bins = 50);

/// Writes `h` as CSV `lo,hi,count,density,maxwell_density` (atomically): bin edges (units
/// of x), counts, the histogram density and the reference's mean density over each bin
/// (both 1 / units of x).
void write_histogram_csv(const std::string& path, const Histogram& h, const MaxwellReference& ref);

}  // namespace hypergas::analysis
