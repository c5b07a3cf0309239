// sim/outputs/conservation.cpp -- conservation.csv and conservation.png: the energy and
// momentum of the gas at every sampling instant against the first one, in the runs whose
// dynamics conserve both (elastic, not sheared, not driven). Columns:
//   time,
//   energy_rel_change   (E - E_1) / E_1, E = sum m |v|^2 / 2 (signed, dimensionless),
//   momentum_drift      |P - P_1| / sum m |v| at the first instant (hypergas/conserved.hpp),
// with E_1, P_1 the first row's (t = 0 for DSMC, the end of the equilibration for EDMD, which
// is elastic too). The sums are those of summary.json's energy_rel_drift and momentum_drift
// (hypergas/conserved.hpp, long double), whose values against t = 0 the last row repeats to
// round-off (a test holds them against each other).
#include <string_view>
#include <vector>

#include "../output_dir.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/checkpoint.hpp"
#include "hypergas/conserved.hpp"
#include "output.hpp"
#include "plot_conservation_gp.hpp"  // generated from scripts/run/conservation.gp

namespace hypergas::cli {

namespace {

class ConservationSeries final : public Observer {
 public:
  void observe(const Snapshot& s) override {
    Conserved<6> c;  // the largest D; the components past s.dim stay 0
    for (std::size_t i = 0; i < s.n; ++i)
      add_particle(c, s.velocities + i * static_cast<std::size_t>(s.stride), s.dim,
                   s.inverse_mass(i));
    if (rows_.empty()) first_ = c;
    const long double e0 = first_.energy;
    rows_.push_back({s.time, e0 > 0.0L ? static_cast<double>((c.energy - e0) / e0) : 0.0,
                     momentum_drift(first_, c)});
  }
  template <class Archive>
  void io(Archive& a) {
    a.tag("conservation");
    a(first_, rows_);  // the first instant's sums exactly, in long double
  }
  const std::vector<std::vector<double>>& rows() const { return rows_; }

 private:
  Conserved<6> first_;
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
