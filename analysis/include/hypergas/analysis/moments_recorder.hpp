// hypergas/analysis/moments_recorder.hpp -- an Observer that records the relaxation to MB.
//
// Per snapshot it records one row of moments.csv (the file contract of docs/design.md).
// Columns, in order:
//   time                     engine time (engine units)
//   collisions_per_particle  2 * collisions / n
//   m2, m4                   <|v|^2>, <|v|^4> over all particles (velocity^2, velocity^4)
//   kurtosis_x               <w_x^4> / <w_x^2>^2 (mass-weighted x component; MB: 3)
//   m6                       <|v|^6> (velocity^6)
//   m2_err, m4_err, m6_err, kurtosis_x_err   standard errors of the above
//   m4_ratio, m4_ratio_err   <w^4> / (D(D+2)(kT/m_mean)^2) and its error (MB: 1)
//   kT                       2 E_kin / (D n), energy units: the reference temperature
//   l1_speed, kl_speed       L1 distance and KL divergence (nats) of the speed histogram
//   ks_p_speed               KS p-value of the speeds against MB at kT (conservative)
//   chi2_p_speed             chi-square p-value of the speed histogram (1 fitted parameter)
//   kT_0, kT_1, ...          per-species temperature, energy units (mixtures only)
// Pooled speeds are mass-weighted (see sample.hpp). The recorder keeps the speed histograms
// of the last snapshot (pooled and, for mixtures, per species) for speed_histogram.csv.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/observer.hpp"

namespace hypergas::analysis {

class MomentsRecorder final : public Observer {
 public:
  /// `bins` bins for the speed histograms (>= 1).
  explicit MomentsRecorder(std::size_t bins = 50);

  /// Records one row; throws InvalidInput for an unreadable snapshot or one whose number of
  /// species differs from the first.
  void observe(const Snapshot& s) override;

  /// Column names, fixed by the first snapshot (the per-species columns need it).
  const std::vector<std::string>& columns() const { return columns_; }
  /// One row per observed snapshot, in column order.
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  /// The values of one column over time; throws InvalidInput for an unknown name.
  std::vector<double> column(const std::string& name) const;

  /// Writes moments.csv (atomically). Throws InvalidInput if nothing was observed.
  void write_moments_csv(const std::string& path) const;
  /// Writes the last snapshot's speed histogram `lo,hi,count,density,maxwell_density`
  /// (speed in velocity units, densities in 1/velocity; MB at that snapshot's kT) of all
  /// particles (species = -1, mass-weighted) or of one species (mixtures).
  void write_speed_histogram_csv(const std::string& path, int species = -1) const;

 private:
  std::size_t bins_;
  int n_species_ = 0;
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
  std::vector<Histogram> last_histograms_;  // pooled, then species 0, 1, ... (mixtures)
  std::vector<MaxwellReference> last_refs_;
  int dim_ = 0;
};

}  // namespace hypergas::analysis
