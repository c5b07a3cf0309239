// sim/outputs/helfand.cpp -- transport.csv and correlations.csv of `run --engine edmd
// --transport`: viscosity, thermal conductivity and self-diffusion of the fluid by
// Einstein-Helfand and Green-Kubo (analysis::HelfandRecorder, kept collision by collision
// over the measurement window), over first Sonine and Enskog.
#include <optional>
#include <string>

#include <fmt/core.h>

#include "../output_dir.hpp"
#include "hypergas/analysis/helfand_recorder.hpp"
#include "output.hpp"
#include "plot_transport_edmd_gp.hpp"  // generated from scripts/run/transport_edmd.gp

namespace hypergas::cli {

namespace {

/// The coefficient a reported part belongs to: viscosity_cross -> viscosity.
std::string whole_coefficient(const std::string& part) {
  for (const char* w : {"thermal_conductivity", "self_diffusion", "viscosity"})
    if (part.rfind(w, 0) == 0) return w;
  return part;
}

class HelfandOutput final : public Output {
 public:
  explicit HelfandOutput(const RunSetup& s) {
    const RunOptions& o = s.options;
    analysis::TransportSettings ts;
    ts.dt = o.correlation_dt;
    ts.max_lag = o.correlation_time;
    ts.tagged = o.tagged;
    recorder_.emplace(ts, o.dim, static_cast<std::size_t>(o.n), s.window_start, o.until);
  }

  Observer* sampler() override { return &*recorder_; }
  void finish() override { recorder_->finish(); }
  void write(OutputDir& out) const override {
    recorder_->write_transport_csv(out.staged("transport.csv").string());
    recorder_->write_correlations_csv(out.staged("correlations.csv").string());
  }
  void summarize(analysis::JsonObject& s) const override {
    s.emplace_back("transport_mean_free_time", recorder_->mean_free_time());
    s.emplace_back("transport_chi", recorder_->chi());
    for (const auto& c : recorder_->finish()) {
      s.emplace_back(c.name, c.value);
      s.emplace_back(c.name + "_error", c.error);
    }
  }
  void report(std::string& text, const analysis::JsonObject&) const override {
    // a part (kinetic, cross, collisional) over the dilute gas's whole first Sonine
    // coefficient, and over Enskog's value of the same part
    for (const auto& c : recorder_->finish())
      text += fmt::format(
          "  {} {:.5g} +- {:.2g} (units sigma, m, kT); over the dilute first Sonine {} "
          "{:.5f} +- {:.5f}; over Enskog's {} {:.5f} +- {:.5f}\n",
          c.name, c.value, c.error, whole_coefficient(c.name), c.ratio, c.ratio_error, c.name,
          c.enskog_ratio, c.enskog_ratio_error);
  }
  std::string_view plot() const override { return embedded::plot_transport_edmd_gp; }

 private:
  // finish() caches its result, so the const accessors above may call it
  mutable std::optional<analysis::HelfandRecorder> recorder_;
};

}  // namespace

namespace outputs {
extern const OutputKind helfand{
    "helfand",
    [](const RunOptions& o, registry::EngineKind e) {
      return o.transport && e == registry::EngineKind::edmd;
    },
    make_output<HelfandOutput>,
    // its correlations or frames are not saved: a resumed run would report a part of the
    // run as the whole
    false};
}

}  // namespace hypergas::cli
