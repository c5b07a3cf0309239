// sim/outputs/moments.hpp -- moments.csv and speed_histogram.csv: the rows of
// analysis::MomentsRecorder at every sampling stop and the final speed histogram, which
// every run has (the granular output reads its rows).
#pragma once

#include "hypergas/analysis/moments_recorder.hpp"
#include "output.hpp"

namespace hypergas::cli {

class MomentsOutput final : public Output {
 public:
  explicit MomentsOutput(const RunSetup& s);

  Observer* sampler() override { return &recorder_; }
  void save(checkpoint::Writer& w) const override { w(recorder_); }
  void load(checkpoint::Reader& r) override { r(recorder_); }
  void write(OutputDir& out) const override;
  void summarize(analysis::JsonObject& s) const override;
  std::string_view plot() const override;

  const analysis::MomentsRecorder& recorder() const { return recorder_; }
  /// The last value of a column of moments.csv.
  double last(const char* column) const { return recorder_.column(column).back(); }

 private:
  analysis::MomentsRecorder recorder_;
};

namespace outputs {
extern const OutputKind moments;
}

}  // namespace hypergas::cli
