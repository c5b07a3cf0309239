// MomentsRecorder: moments, distances and tests per snapshot; moments.csv and the final
// speed histogram.
#include "hypergas/analysis/moments_recorder.hpp"

#include <algorithm>
#include <cmath>

#include "hypergas/analysis/moments.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/analysis/statistics.hpp"
#include "hypergas/error.hpp"

namespace hypergas::analysis {

MomentsRecorder::MomentsRecorder(std::size_t bins) : bins_(bins) {
  if (bins < 1) throw InvalidInput("MomentsRecorder: need at least one histogram bin");
}

void MomentsRecorder::observe(const Snapshot& s) {
  validate(s);
  if (s.n < 2) throw InvalidInput("MomentsRecorder: need at least 2 particles");
  const int ns = s.species ? s.n_species : 1;
  if (columns_.empty()) {
    n_species_ = ns;
    dim_ = s.dim;
    columns_ = {"time",        "collisions_per_particle",
                "m2",          "m4",
                "kurtosis_x",  "m6",
                "m2_err",      "m4_err",
                "m6_err",      "kurtosis_x_err",
                "m4_ratio",    "m4_ratio_err",
                "kT",          "l1_speed",
                "kl_speed",    "ks_p_speed",
                "chi2_p_speed"};
    if (ns > 1)
      for (int k = 0; k < ns; ++k) columns_.push_back("kT_" + std::to_string(k));
  } else if (ns != n_species_ || s.dim != dim_) {
    throw InvalidInput("MomentsRecorder: snapshot dimension or species count changed");
  }

  const Moments m = compute_moments(s);
  const MaxwellReference ref = reference(s, Quantity::speed);
  const std::vector<double> speeds = values(s, Quantity::speed);
  Histogram h = make_histogram(speeds, ref, bins_);
  // kT comes from the same sample: one fitted parameter for the chi-square test.
  const double chi2_p = chi_square_test(h, ref, 1).p_value;
  std::vector<double> row = {s.time,
                             s.collisions_per_particle,
                             m.m2.value,
                             m.m4.value,
                             m.kurtosis_x.value,
                             m.m6.value,
                             m.m2.error,
                             m.m4.error,
                             m.m6.error,
                             m.kurtosis_x.error,
                             m.m4_ratio.value,
                             m.m4_ratio.error,
                             m.kT,
                             l1_distance(h, ref),
                             kl_divergence(h, ref),
                             ks_test(speeds, ref).p_value,
                             chi2_p};
  last_histograms_.clear();
  last_refs_.clear();
  last_histograms_.push_back(std::move(h));
  last_refs_.push_back(ref);
  if (ns > 1) {
    for (int k = 0; k < ns; ++k) {
      const bool present = count(s, k) > 0;
      row.push_back(present ? temperature(s, k) : NAN);
      // Species histograms: each species' own speeds against MB at the common kT.
      const MaxwellReference rk = present ? reference(s, Quantity::speed, k) : ref;
      last_histograms_.push_back(make_histogram(
          present ? values(s, Quantity::speed, k) : std::vector<double>{}, rk, bins_));
      last_refs_.push_back(rk);
    }
  }
  rows_.push_back(std::move(row));
}

std::vector<double> MomentsRecorder::column(const std::string& name) const {
  const auto it = std::find(columns_.begin(), columns_.end(), name);
  if (it == columns_.end()) throw InvalidInput("MomentsRecorder: no column '" + name + "'");
  const auto c = static_cast<std::size_t>(it - columns_.begin());
  std::vector<double> out;
  out.reserve(rows_.size());
  for (const auto& r : rows_) out.push_back(r[c]);
  return out;
}

void MomentsRecorder::write_moments_csv(const std::string& path) const {
  if (rows_.empty()) throw InvalidInput("MomentsRecorder: nothing observed, no " + path);
  write_csv(path, columns_, rows_);
}

void MomentsRecorder::write_speed_histogram_csv(const std::string& path, int species) const {
  if (last_histograms_.empty()) throw InvalidInput("MomentsRecorder: nothing observed, no " + path);
  const auto k = static_cast<std::size_t>(species + 1);
  if (species < -1 || k >= last_histograms_.size())
    throw InvalidInput("MomentsRecorder: no species " + std::to_string(species) + " for " + path);
  write_histogram_csv(path, last_histograms_[k], last_refs_[k]);
}

}  // namespace hypergas::analysis
