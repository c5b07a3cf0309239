// sim/outputs/helfand.cpp -- transport.csv and correlations.csv of `run --engine edmd
// --transport`: viscosity, thermal conductivity and self-diffusion of the fluid by
// Einstein-Helfand and Green-Kubo (analysis::HelfandRecorder, kept collision by collision
// over the measurement window), over first Sonine and Enskog.
#include <optional>
#include <set>
#include <string>

#include <fmt/core.h>

#include "../output_dir.hpp"
#include "hypergas/analysis/helfand_recorder.hpp"
#include "output.hpp"
#include "route_check.hpp"
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
    correlation_time_ = o.correlation_time;
    ts.tagged = o.was_given("--tagged") ? o.tagged : options::edmd_tagged;
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
    const auto& rows = recorder_->finish();
    for (const auto& c : rows) {
      s.emplace_back(c.name, c.value);
      s.emplace_back(c.name + "_error", c.error);
    }
    // every coefficient with two routes: Einstein-Helfand against Green-Kubo
    check_rows(s, rows, "viscosity", "viscosity_green_kubo");
    check_rows(s, rows, "thermal_conductivity", "thermal_conductivity_green_kubo");
    check_rows(s, rows, "self_diffusion", "self_diffusion_einstein");
    // a coefficient whose remainder beyond the cut exceeds its statistical error is said:
    // its error is then mostly the truncation's
    for (const auto& c : rows)
      if (c.name == whole_coefficient(c.name) && c.truncation_error > c.statistical_error &&
          plateau_note_.insert(whole_coefficient(c.name)).second)
        fmt::print(stderr,
                   "hypergas: note: {}: the running integral has no plateau within "
                   "--correlation-time {:g} mean free times (truncation error {:.2g} against "
                   "statistical {:.2g}, both in its stated error): a longer "
                   "--correlation-time shrinks it\n",
                   c.name, correlation_time_, c.truncation_error, c.statistical_error);
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
  double correlation_time_ = 0.0;
  mutable std::set<std::string> plateau_note_;  // said once per coefficient
};

}  // namespace

namespace outputs {
constexpr std::string_view helfand_files[] = {"transport.csv", "correlations.csv",
                                             "transport.png"};
extern const OutputKind helfand{
    .name = "helfand",
    .wanted = [](const RunOptions& o,
                 registry::EngineKind e) { return o.transport && e == registry::EngineKind::edmd; },
    .make = make_output<HelfandOutput>,
    // its correlations or frames are not saved: a resumed run would report a part of the
    // run as the whole
    .checkpointable = false,
    .files = helfand_files};
}

}  // namespace hypergas::cli
