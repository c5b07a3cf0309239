// sim/outputs/vacf.cpp -- vacf.csv (EDMD): the velocity autocorrelation of up to 2000
// particles by multiple-tau correlation (analysis::VacfRecorder) at the sampling stops, and
// the summary key diffusion_green_kubo, its Green-Kubo integral divided by D. The VACF
// decays over about a mean free time, so its trapezoid integral is only trusted where the
// sampling interval is at most max_vacf_step mean free times: beyond, diffusion_green_kubo
// is null and the text says which --every would give it (vacf_dt states the interval).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/core.h>

#include "../output_dir.hpp"
#include "../run_summary.hpp"
#include "output.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "plot_vacf_gp.hpp"  // generated from scripts/run/vacf.gp

namespace hypergas::cli {

namespace {

/// Particles whose velocities the VACF follows.
constexpr std::size_t vacf_particles = 2000;
/// The largest sampling interval, in mean free times, whose Green-Kubo integral is given: an
/// exponential decay over tau integrated by the trapezoid rule with step h is high by about
/// h^2 / (12 tau^2) (0.5 % here); 4D, packing 0.2: 0.201 at h = 5.6 tau against 0.131 from
/// the MSD slope.
constexpr double max_vacf_step = 0.25;

/// Whether the VACF's step resolves its decay, from the run's mean free time.
bool resolved(double dt, const analysis::JsonObject& s) {
  const double tau = summary_number(s, "mean_free_time");
  return std::isfinite(tau) && tau > 0.0 && dt <= max_vacf_step * tau;
}

class VacfOutput final : public Output {
 public:
  explicit VacfOutput(const RunSetup& s)
      : recorder_(std::min<std::size_t>(static_cast<std::size_t>(s.options.n), vacf_particles)) {}

  Observer* sampler() override { return &recorder_; }
  void save(checkpoint::Writer& w) const override { w(recorder_); }
  void load(checkpoint::Reader& r) override { r(recorder_); }
  void write(OutputDir& out) const override {
    if (recorder_.frames() >= 2) recorder_.write_csv(out.staged("vacf.csv").string());
  }
  void summarize(analysis::JsonObject& s) const override {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    const bool ok = recorder_.frames() >= 2 && resolved(recorder_.dt(), s);
    s.emplace_back("vacf_dt", recorder_.dt());
    s.emplace_back("diffusion_green_kubo", ok ? recorder_.green_kubo() : nan);
  }
  void report(std::string& text, const analysis::JsonObject& s) const override {
    const double tau = summary_number(s, "mean_free_time");
    // no collisions (no finite mean free time): nothing to resolve, nothing to say
    if (recorder_.frames() < 2 || resolved(recorder_.dt(), s) || !std::isfinite(tau) ||
        !(tau > 0.0))
      return;
    text += fmt::format(
        "  diffusion_green_kubo not given: the VACF is sampled every {:.3g} mean free times; "
        "--every {:.2g} or less resolves its decay\n",
        recorder_.dt() / tau, max_vacf_step * tau);
  }
  std::string_view plot() const override {
    return recorder_.frames() >= 2 ? embedded::plot_vacf_gp : std::string_view{};
  }

 private:
  analysis::VacfRecorder recorder_;
};

}  // namespace

namespace outputs {
extern const OutputKind vacf{
    "vacf",
    [](const RunOptions&, registry::EngineKind e) { return e == registry::EngineKind::edmd; },
    make_output<VacfOutput>};
}

}  // namespace hypergas::cli
