// sim/outputs/pressure.cpp -- the errors of the elastic EDMD run's equilibrium measures
// (summary keys Z_error, collision_rate_error). The engine's measurement window gives Z and
// the collision rate over the whole window (summary keys Z, collision_rate); each snapshot
// shows the window's virial and collisions so far (Snapshot::window_*), so each sampling
// interval has its own Z_k = 1 + dW / (D N kT dt) and rate_k = 2 dC / (N dt), whose mean
// is the window's value. Their standard errors come from block averages
// (analysis/estimates.hpp): `blocks` blocks of consecutive intervals, longer than the
// correlation time of the pressure (a few mean free times) at the default sampling. Under
// shear Z is undefined (edmd::has_pressure_Z) and so is its error: Z_error is null.
#include <cmath>
#include <limits>
#include <vector>

#include "../output_dir.hpp"
#include "hypergas/analysis/estimates.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/checkpoint.hpp"
#include "hypergas/edmd/observables.hpp"
#include "output.hpp"

namespace hypergas::cli {

namespace {

/// Blocks of the errors; fewer intervals than 2 per block give no error (null).
constexpr std::size_t pressure_blocks = 10;

/// Z and the collision rate of each sampling interval in the measurement window.
class Intervals final : public Observer {
 public:
  void observe(const Snapshot& s) override {
    if (!std::isfinite(s.window_start)) return;
    if (s.window_start == start_ && s.time > time_) {
      const double n = static_cast<double>(s.n), dt = s.time - time_;
      const double kT = analysis::temperature(s);  // sum m v^2 / (D N)
      z_.push_back(1.0 + (s.window_virial - virial_) / (s.dim * n * kT * dt));
      rate_.push_back(2.0 * static_cast<double>(s.window_collisions - collisions_) / (n * dt));
    }
    time_ = s.time;
    start_ = s.window_start;
    virial_ = s.window_virial;
    collisions_ = s.window_collisions;
  }
  void save(checkpoint::Writer& w) const { w(time_, start_, virial_, collisions_, z_, rate_); }
  void load(checkpoint::Reader& r) { r(time_, start_, virial_, collisions_, z_, rate_); }
  analysis::MeanSe z() const { return estimate(z_); }
  analysis::MeanSe rate() const { return estimate(rate_); }

 private:
  static analysis::MeanSe estimate(const std::vector<double>& x) {
    if (x.size() < 2 * pressure_blocks) return {};
    return analysis::block_average(x, 0, x.size(), pressure_blocks);
  }

  double time_ = std::numeric_limits<double>::quiet_NaN();
  double start_ = std::numeric_limits<double>::quiet_NaN();
  double virial_ = 0.0;
  std::uint64_t collisions_ = 0;
  std::vector<double> z_, rate_;
};

class PressureOutput final : public Output {
 public:
  explicit PressureOutput(const RunSetup& setup)
      : z_defined_(edmd::has_pressure_Z(setup.options.restitution, setup.options.shear_rate)) {}

  Observer* sampler() override { return &intervals_; }
  void save(checkpoint::Writer& w) const override { intervals_.save(w); }
  void load(checkpoint::Reader& r) override { intervals_.load(r); }
  void write(OutputDir&) const override {}
  void summarize(analysis::JsonObject& s) const override {
    s.emplace_back("Z_error",
                   z_defined_ ? intervals_.z().se : std::numeric_limits<double>::quiet_NaN());
    s.emplace_back("collision_rate_error", intervals_.rate().se);
  }

 private:
  bool z_defined_;
  Intervals intervals_;
};

}  // namespace

namespace outputs {
extern const OutputKind pressure{
    .name = "pressure",
    .wanted =
        [](const RunOptions& o, registry::EngineKind e) {
          return e == registry::EngineKind::edmd && o.restitution == 1.0;
        },
    .make = make_output<PressureOutput>};
}

}  // namespace hypergas::cli
