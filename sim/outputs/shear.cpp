// sim/outputs/shear.cpp -- the rheology of a sheared gas (--shear-rate a; dsmc/shear.hpp,
// edmd/lees_edwards.hpp): pressure_tensor.csv and the steady state's summary keys.
//
// EDMD rows hold the exact pressure tensor, kinetic and collisional, averaged over each
// sampling interval (their _err columns are NaN, written empty), with the interval's mean
// kinetic temperature; real_time is in ideal-gas mean collision times at T0, and
// viscosity_ratio is against the Boltzmann gas's first Sonine value (the dense gas's own
// differs by the Enskog terms, O(packing)).
//
// pressure_tensor.csv (analysis/pressure_tensor_recorder.hpp), one row per sampling
// instant: time, real_time (mean collision times at the initial temperature T0),
// temperature_ratio T/T0, reduced_shear_rate (a per mean collision time at the current T:
// a (T/T0)^(-a_m/2), a_m the model's rate exponent), then each component P_ij / p for
// i <= j followed by its standard error over the particles (P_xx, P_xx_err, P_xy,
// P_xy_err, ...; axes x, y, z, u, v, w; the flow is along x, its gradient along y).
// DSMC: P = sum m V V^T / (N - 1) and p = tr P / D = kT, the engine's temperature; V are
// the peculiar velocities (those of the frame moving with the flow). EDMD: p = tr P / D of
// the interval's whole tensor, kinetic and collisional, not n kT.
//
// Summary keys, from the steady state: the rows of the second half of the run
// (time >= until / 2), their means and standard errors from 10 blocks (blocks longer than
// the stress's relaxation time, 2 mean collision times, at the default sampling):
//   shear_stress (P_xy / p), normal_stress_xx ((P_xx - p) / p), normal_stress_yy,
//   reduced_shear_rate,
//   viscosity_ratio: eta(a) = -P_xy / (p a*) (a* the reduced shear rate) over the a -> 0
//     value of the model: its first Sonine viscosity (analysis/transport_recorder.hpp; exact
//     for Maxwell molecules, where eta(0) = 2 mean collision times x p),
//   thermostat_rate (--thermostat isokinetic): zeta = -a* P_xy / (D p) per mean collision time,
//   heating_rate (--thermostat none): d ln T / d real_time from the rows' temperatures, per
//     mean collision time at T0 (a growth with viscous heating, 0 in a granular steady state),
//   temperature_ratio (--restitution < 1): T / T0 of the granular steady state;
// each with `_error`.
//
// rheology.png (scripts/run/shear.gp): -P_xy / p, the normal stress differences and T / T0
// against real_time, with the steady state's means of the same rows as the summary.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "../output_dir.hpp"
#include "hypergas/analysis/estimates.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/pressure_tensor_recorder.hpp"
#include "hypergas/analysis/transport_recorder.hpp"
#include "hypergas/checkpoint.hpp"
#include "output.hpp"
#include "../run_summary.hpp"
#include <fmt/core.h>

#include "plot_shear_gp.hpp"  // generated from scripts/run/shear.gp

namespace hypergas::cli {

namespace {

constexpr std::size_t shear_blocks = 10;

class ShearOutput final : public Output {
 public:
  explicit ShearOutput(const RunSetup& s)
      : until_(s.options.until),
        rate_(s.options.shear_rate),
        isokinetic_(s.options.thermostat == dsmc::Thermostat::isokinetic),
        granular_(s.options.restitution != 1.0),
        edmd_(s.engine == registry::EngineKind::edmd),
        dim_(s.options.dim),
        tensor_(s.options.dim, s.options.shear_rate, law(s).exponent) {
    eta0_ = analysis::first_sonine(law(s), s.options.dim)[0];
  }
  /// The collision law: the model's (DSMC), hard spheres (EDMD).
  static analysis::CollisionLaw law(const RunSetup& s) {
    const registry::ModelTraits m =
        s.engine == registry::EngineKind::edmd
            ? registry::model_traits("hs", s.options.vhs_exponent)
            : registry::model_traits(s.options.model, s.options.vhs_exponent);
    return analysis::CollisionLaw{m.exponent, m.isotropic_scattering};
  }

  Observer* sampler() override { return &tensor_; }
  void save(checkpoint::Writer& w) const override { w(tensor_); }
  void load(checkpoint::Reader& r) override { r(tensor_); }
  void write(OutputDir& out) const override {
    analysis::write_csv(out.staged("pressure_tensor.csv").string(), tensor_.columns(),
                        tensor_.rows());
  }
  void summarize(analysis::JsonObject& s) const override {
    s.emplace_back("shear_rate", rate_);
    s.emplace_back("thermostat", std::string(isokinetic_ ? "isokinetic" : "none"));
    const auto& rows = tensor_.rows();
    const std::size_t b = steady_begin(), e = rows.size();
    const auto put = [&](const std::string& key, auto&& value_of) {
      const analysis::MeanSe m = steady(value_of);
      s.emplace_back(key, m.mean);
      s.emplace_back(key + "_error", m.se);
    };
    const std::size_t xy = tensor_.column(0, 1), xx = tensor_.column(0, 0),
                      yy = tensor_.column(1, 1);
    const double d = dim_;
    put("shear_stress", [&](const auto& r) { return r[xy]; });
    put("normal_stress_xx", [&](const auto& r) { return r[xx] - 1.0; });
    put("normal_stress_yy", [&](const auto& r) { return r[yy] - 1.0; });
    put("reduced_shear_rate", [&](const auto& r) { return r[3]; });
    put("viscosity_ratio", [&](const auto& r) { return -r[xy] / r[3] / eta0_; });
    if (isokinetic_) {
      put("thermostat_rate", [&](const auto& r) { return -r[3] * r[xy] / d; });
    } else {
      // d ln T / d real_time: each block's increments of ln T over those of real time
      analysis::MeanSe h;
      if (e - b >= 2 * shear_blocks)
        h = analysis::over_blocks(b, e - 1, shear_blocks, [&](std::size_t i, std::size_t j) {
          return std::log(rows[j][2] / rows[i][2]) / (rows[j][1] - rows[i][1]);
        });
      s.emplace_back("heating_rate", h.mean);
      s.emplace_back("heating_rate_error", h.se);
    }
    if (granular_) put("temperature_ratio", [&](const auto& r) { return r[2]; });
  }
  void report(std::string& text, const analysis::JsonObject& summary) const override {
    if (!std::isfinite(summary_number(summary, "shear_stress_error"))) {
      text += fmt::format("  shear flow a = {}: fewer than {} samples in the second half of the "
                          "run, no steady state (pressure_tensor.csv has every sample)\n",
                          rate_, 2 * shear_blocks);
      return;
    }
    const auto pm = [&](const char* k) {
      return fmt::format("{:.5g} +- {:.2g}", summary_number(summary, k),
                         summary_number(summary, std::string(k) + "_error"));
    };
    text += fmt::format("  shear flow a = {} ({}): P_xy/p = {}, (P_xx-p)/p = {}, "
                        "(P_yy-p)/p = {}, eta(a)/eta(0) = {} (second half; pressure_tensor.csv)\n",
                        rate_, isokinetic_ ? "isokinetic" : "no thermostat",
                        pm("shear_stress"), pm("normal_stress_xx"), pm("normal_stress_yy"),
                        pm("viscosity_ratio"));
  }
  /// rheology.png (scripts/run/shear.gp), after the variables it reads: the steady state's
  /// means it draws are the summary's (steady()).
  std::string_view plot() const override {
    const std::size_t xy = tensor_.column(0, 1), xx = tensor_.column(0, 0),
                      yy = tensor_.column(1, 1);
    const double n2 =
        dim_ >= 3 ? steady([&](const auto& r) { return r[yy] - r[tensor_.column(2, 2)]; }).mean
                  : std::numeric_limits<double>::quiet_NaN();
    const auto number = [](double x) {
      return std::isfinite(x) ? fmt::format("{:.17g}", x) : std::string("NaN");
    };
    script_ = fmt::format(
        "shear_dim = {}\nshear_errors = {}\nshear_time_unit = \"{}\"\nshear_from = {}\n"
        "shear_stress = {}\nshear_n1 = {}\nshear_n2 = {}\n",
        dim_, edmd_ ? 0 : 1,
        edmd_ ? "ideal-gas mean collision times at T0" : "mean collision times at T0",
        number(0.5 * until_), number(steady([&](const auto& r) { return r[xy]; }).mean),
        number(steady([&](const auto& r) { return r[xx] - r[yy]; }).mean), number(n2));
    script_ += embedded::plot_shear_gp;
    return script_;
  }

 private:
  /// The first row of the steady state: the second half of the run (time >= until / 2).
  std::size_t steady_begin() const {
    const auto& rows = tensor_.rows();
    std::size_t b = 0;
    while (b < rows.size() && rows[b][0] < 0.5 * until_) ++b;
    return b;
  }
  /// The steady state's mean of value_of(row) and its standard error from shear_blocks
  /// blocks; NaN with fewer than 2 shear_blocks rows.
  template <class F>
  analysis::MeanSe steady(F&& value_of) const {
    const auto& rows = tensor_.rows();
    const std::size_t b = steady_begin(), e = rows.size();
    if (e - b < 2 * shear_blocks) return {};
    std::vector<double> y;
    for (std::size_t i = b; i < e; ++i) y.push_back(value_of(rows[i]));
    return analysis::block_average(y, 0, y.size(), shear_blocks);
  }

  double until_, rate_;
  bool isokinetic_, granular_, edmd_;
  int dim_;
  analysis::PressureTensorRecorder tensor_;
  double eta0_ = 1.0;
  mutable std::string script_;  // plot()'s text
};

}  // namespace

namespace outputs {
constexpr std::string_view shear_files[] = {"pressure_tensor.csv", "rheology.png"};
// a sheared granular gas has a steady state, whose keys this output writes
constexpr std::string_view shear_excludes[] = {"granular"};
extern const OutputKind shear{
    .name = "shear",
    .wanted = [](const RunOptions& o, registry::EngineKind) { return o.shear_rate != 0.0; },
    .make = make_output<ShearOutput>,
    .files = shear_files,
    .excludes = shear_excludes};
}

}  // namespace hypergas::cli
