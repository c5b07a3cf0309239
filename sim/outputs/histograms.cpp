// sim/outputs/histograms.cpp -- speed_histograms.csv with --histogram-every T: the speed
// histogram of the whole gas at sampling instants about T apart, to watch a relaxation (or
// a cooling) from the command. Every m-th sampling instant is taken, m = max(1, round(T /
// every)) with `every` the sampling interval in use, from the first; the file has one row
// per bin and time: time,lo,hi,count,density,maxwell_density (50 bins over the range of
// speed_histogram.csv's, the Maxwell-Boltzmann density at that instant's temperature). In
// a freely cooling DSMC gas the speeds are the stored, scaled ones (as in moments.csv's
// a2): the shapes compare, the scale is the initial temperature's.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../output_dir.hpp"
#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/sample.hpp"
#include "output.hpp"
#include "plot_histograms_gp.hpp"  // generated from scripts/run/histograms.gp

namespace hypergas::cli {

namespace {

/// Bins of each histogram (those of speed_histogram.csv).
constexpr std::size_t histogram_bins = 50;

class Series final : public Observer {
 public:
  explicit Series(std::uint64_t stride) : stride_(stride) {}
  void observe(const Snapshot& s) override {
    if (seen_++ % stride_ != 0) return;
    const analysis::MaxwellReference ref = analysis::reference(s, analysis::Quantity::speed);
    const analysis::Histogram h =
        analysis::make_histogram(analysis::values(s, analysis::Quantity::speed), ref,
                                 histogram_bins);
    for (std::size_t i = 0; i < h.bins(); ++i)
      rows_.push_back({s.time, h.lower(i), h.upper(i), h.count(i), h.density(i),
                       analysis::bin_density(ref, h.lower(i), h.upper(i))});
  }
  template <class Archive>
  void io(Archive& a) {
    a.tag("speed-histograms");
    a(seen_, rows_);  // the stride follows from the options, which a resume parses again
  }
  const std::vector<std::vector<double>>& rows() const { return rows_; }

 private:
  const std::uint64_t stride_;
  std::uint64_t seen_ = 0;
  std::vector<std::vector<double>> rows_;
};

class HistogramsOutput final : public Output {
 public:
  explicit HistogramsOutput(const RunSetup& s)
      : series_(sampling_stride(s.plan, s.options.histogram_every)) {}

  Observer* sampler() override { return &series_; }
  void save(checkpoint::Writer& w) const override { w(series_); }
  void load(checkpoint::Reader& r) override { r(series_); }
  void write(OutputDir& out) const override {
    analysis::write_csv(out.staged("speed_histograms.csv").string(),
                        {"time", "lo", "hi", "count", "density", "maxwell_density"},
                        series_.rows());
  }
  std::string_view plot() const override { return embedded::plot_histograms_gp; }

 private:
  Series series_;
};

}  // namespace

namespace outputs {
constexpr std::string_view histograms_files[] = {"speed_histograms.csv", "speed_histograms.png"};
extern const OutputKind histograms{
    .name = "histograms",
    .wanted = [](const RunOptions& o, registry::EngineKind) { return o.histogram_every > 0.0; },
    .make = make_output<HistogramsOutput>,
    .files = histograms_files};
}

}  // namespace hypergas::cli
