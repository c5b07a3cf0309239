// sim/outputs/conservation.cpp -- conservation.csv and conservation.png: the energy and
// momentum of the gas at every sampling instant against the first one, in the runs whose
// dynamics conserve both (elastic, not sheared, not driven). Columns:
//   time,
//   energy_rel_change   (E - E_1) / E_1, E = sum m |v|^2 / 2 (signed, dimensionless),
//   momentum_drift      |P - P_1| / sum m |v| at the first instant (hypergas/conserved.hpp),
// with E_1, P_1 the first row's (t = 0 for DSMC, the end of the equilibration for EDMD, which
// is elastic too). The sums are in long double, as those of summary.json's energy_rel_drift
// and momentum_drift, whose values against t = 0 the last row repeats to round-off (a test
// holds them against each other). Particles of infinite mass carry no energy and are left out.
#include <array>
#include <cmath>
#include <limits>
#include <string_view>
#include <vector>

#include "../output_dir.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/checkpoint.hpp"
#include "output.hpp"
#include "plot_conservation_gp.hpp"  // generated from scripts/run/conservation.gp

namespace hypergas::cli {

namespace {

class ConservationSeries final : public Observer {
 public:
  void observe(const Snapshot& s) override {
    long double energy = 0.0L, scale = 0.0L;
    std::array<long double, 6> p{};
    for (std::size_t i = 0; i < s.n; ++i) {
      const double w = s.inverse_mass(i);
      if (!(w > 0.0)) continue;
      const long double m = 1.0L / w;
      const double* v = s.velocities + i * static_cast<std::size_t>(s.stride);
      long double v2 = 0.0L;
      for (int k = 0; k < s.dim; ++k) {
        const long double vk = v[k];
        v2 += vk * vk;
        p[k] += m * vk;
      }
      energy += 0.5L * m * v2;
      scale += m * std::sqrt(v2);
    }
    if (rows_.empty()) {
      energy0_ = split(energy);
      scale0_ = split(scale);
      for (int k = 0; k < 6; ++k) momentum0_[k] = split(p[k]);
    }
    const long double e0 = join(energy0_), s0 = join(scale0_);
    long double d2 = 0.0L;
    for (int k = 0; k < s.dim; ++k) {
      const long double dp = p[k] - join(momentum0_[k]);
      d2 += dp * dp;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    rows_.push_back({s.time, e0 > 0.0L ? static_cast<double>((energy - e0) / e0) : nan,
                     s0 > 0.0L ? static_cast<double>(std::sqrt(d2) / s0) : nan});
  }
  template <class Archive>
  void io(Archive& a) {
    a.tag("conservation");
    a(energy0_, scale0_, momentum0_, rows_);
  }
  const std::vector<std::vector<double>>& rows() const { return rows_; }

 private:
  /// A long double as the sum of two doubles (exact for the 64-bit significand), so that a
  /// checkpoint holds the first instant's sums exactly and the first row is exactly 0.
  using Split = std::array<double, 2>;
  static Split split(long double x) {
    const double hi = static_cast<double>(x);
    return {hi, static_cast<double>(x - hi)};
  }
  static long double join(const Split& x) {
    return static_cast<long double>(x[0]) + static_cast<long double>(x[1]);
  }

  Split energy0_{}, scale0_{};
  std::array<Split, 6> momentum0_{};
  std::vector<std::vector<double>> rows_;
};

class ConservationOutput final : public Output {
 public:
  explicit ConservationOutput(const RunSetup&) {}
  Observer* sampler() override { return &series_; }
  void save(checkpoint::Writer& w) const override { w(series_); }
  void load(checkpoint::Reader& r) override { r(series_); }
  void write(OutputDir& out) const override {
    analysis::write_csv(out.staged("conservation.csv").string(),
                        {"time", "energy_rel_change", "momentum_drift"}, series_.rows());
  }
  std::string_view plot() const override { return embedded::plot_conservation_gp; }

 private:
  ConservationSeries series_;
};

constexpr std::string_view conservation_files[] = {"conservation.csv", "conservation.png"};

}  // namespace

namespace outputs {
extern const OutputKind conservation{
    .name = "conservation",
    .wanted =
        [](const RunOptions& o, registry::EngineKind) {
          return o.restitution == 1.0 && o.shear_rate == 0.0 && o.drive == dsmc::Drive::none;
        },
    .make = make_output<ConservationOutput>,
    .files = conservation_files};
}

}  // namespace hypergas::cli
