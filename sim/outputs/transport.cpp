// sim/outputs/transport.cpp -- transport.csv and correlations.csv of `run --engine dsmc
// --transport`: Green-Kubo viscosity, thermal conductivity and self-diffusion of the
// Boltzmann gas (analysis::TransportRecorder) on a fine grid of about --correlation-dt,
// over their first Sonine values.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include <fmt/core.h>

#include "../output_dir.hpp"
#include "hypergas/analysis/transport_recorder.hpp"
#include "output.hpp"
#include "route_check.hpp"
#include "plot_transport_dsmc_gp.hpp"  // generated from scripts/run/transport_dsmc.gp

namespace hypergas::cli {

namespace {

class TransportOutput final : public Output {
 public:
  explicit TransportOutput(const RunSetup& s) {
    const RunOptions& o = s.options;
    // the fine grid (OutputKind::substeps) and the samples the recorder will take (the
    // fine stops from transport_warmup on)
    const RunPlan& plan = s.plan;
    const double dt = plan.sampling.every() / static_cast<double>(plan.substeps);
    std::uint64_t frames = 0;
    for (std::uint64_t k = 0;; ++k) {
      const std::optional<Stop> stop = plan.stop(k);
      if (!stop) break;
      frames += stop->time >= options::transport_warmup - 1e-9 * options::transport_warmup;
    }
    analysis::TransportSettings ts;
    ts.dt = dt;
    ts.max_lag = o.correlation_time;
    // the lanes scheme moves particles between slots: no tagged particles, no self-diffusion
    ts.tagged = o.scheme == dsmc::Scheme::lanes ? 0 : o.tagged;
    ts.warmup = options::transport_warmup;
    ts.seed = o.seed;
    const registry::ModelTraits m = registry::model_traits(o.model, o.vhs_exponent);
    law_ = analysis::CollisionLaw{m.exponent, m.isotropic_scattering};
    dim_ = o.dim;
    recorder_.emplace(ts, o.dim, static_cast<std::size_t>(o.n), frames, law_);
  }

  Observer* fine() override { return &*recorder_; }
  void finish() override { recorder_->finish(); }
  void write(OutputDir& out) const override {
    recorder_->write_transport_csv(out.staged("transport.csv").string());
    recorder_->write_correlations_csv(out.staged("correlations.csv").string());
  }
  void summarize(analysis::JsonObject& s) const override {
    s.emplace_back("transport_dt", recorder_->dt());
    s.emplace_back("transport_samples", static_cast<std::int64_t>(recorder_->frames()));
    for (const auto& c : recorder_->finish()) {
      s.emplace_back(c.name, c.value);
      s.emplace_back(c.name + "_error", c.error);
      s.emplace_back(c.name + "_ratio", c.ratio);
      s.emplace_back(c.name + "_ratio_error", c.ratio_error);
    }
    // the one coefficient with two routes here: tagged velocities against displacements
    check_rows(s, recorder_->finish(), "self_diffusion", "self_diffusion_einstein");
  }
  void report(std::string& text, const analysis::JsonObject&) const override {
    // reduced: eta / (n kT tau), lambda / (n k (kT/m) tau), D_s / ((kT/m) tau)
    for (const auto& c : recorder_->finish()) {
      text += fmt::format(
          "  {} {:.5g} +- {:.2g} (reduced by n, kT, m and the mean collision time); first "
          "Sonine {:.5g}: ratio {:.5f} +- {:.5f}",
          c.name, c.value, c.error, c.sonine, c.ratio, c.ratio_error);
      const double conv = analysis::converged_over_sonine(law_, dim_, c.name);
      if (std::isfinite(conv))
        text += fmt::format("; converged Chapman-Enskog (Pekeris-Alterman) {:.5g}: ratio "
                            "{:.5f} +- {:.5f}",
                            conv * c.sonine, c.ratio / conv, c.ratio_error / conv);
      text += "\n";
    }
  }
  std::string_view plot() const override { return embedded::plot_transport_dsmc_gp; }

 private:
  // finish() caches its result, so the const accessors above may call it
  mutable std::optional<analysis::TransportRecorder> recorder_;
  analysis::CollisionLaw law_;
  int dim_ = 0;
};

}  // namespace

namespace outputs {
constexpr std::string_view transport_files[] = {"transport.csv", "correlations.csv",
                                               "transport.png"};
extern const OutputKind transport{
    .name = "transport",
    .wanted = [](const RunOptions& o,
                 registry::EngineKind e) { return o.transport && e == registry::EngineKind::dsmc; },
    .make = make_output<TransportOutput>,
    // its correlations or frames are not saved: a resumed run would report a part of the
    // run as the whole
    .checkpointable = false,
    .files = transport_files,
    // the correlations' grid: about --correlation-dt between fine stops
    .substeps = [](const RunOptions& o, const Schedule& sampling) {
      return std::max<std::uint64_t>(
          1, static_cast<std::uint64_t>(std::llround(sampling.every() / o.correlation_dt)));
    }};
}

}  // namespace hypergas::cli
