// sim/outputs/vacf.cpp -- vacf.csv (EDMD): the velocity autocorrelation of up to 2000
// particles by multiple-tau correlation (analysis::VacfRecorder) at the sampling stops, and
// the summary key diffusion_green_kubo, its Green-Kubo integral divided by D.
#include <algorithm>

#include "../output_dir.hpp"
#include "output.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "plot_vacf_gp.hpp"  // generated from scripts/run/vacf.gp

namespace hypergas::cli {

namespace {

/// Particles whose velocities the VACF follows.
constexpr std::size_t vacf_particles = 2000;

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
    s.emplace_back("diffusion_green_kubo", recorder_.frames() >= 2 ? recorder_.green_kubo() : 0.0);
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
