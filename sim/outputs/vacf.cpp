// sim/outputs/vacf.cpp -- vacf.csv (EDMD): the velocity autocorrelation of up to 2000
// particles by multiple-tau correlation (analysis::VacfRecorder), and the summary keys of
// its self-diffusion coefficient (VacfRecorder::diffusion: the plateau rule of every EDMD
// transport coefficient, with its statistical and truncation errors): diffusion_green_kubo
// and the Einstein route diffusion_einstein from the MSD, held against each other in every
// run (diffusion_green_kubo_route_difference_se, route_check.hpp). The VACF decays over about a
// mean free time, so it is sampled on a grid of its own, about a tenth of the mean free
// time estimated before the run (vacf_step), whatever --every is: the run makes fine stops
// between its sampling instants (RunPlan::substeps), where the engine copies only the
// followed particles. vacf_dt states the grid; where it still exceeds max_vacf_step
// measured mean free times, diffusion_green_kubo is null and the text says so.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/core.h>

#include "../output_dir.hpp"
#include "../run_summary.hpp"
#include "output.hpp"
#include "route_check.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
#include "hypergas/granular/theory.hpp"
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

/// The VACF's sampling step, in mean free times estimated before the run
/// (estimated_mean_free_time): the trapezoid rule on an exponential decay over tau is then
/// high by about h^2 / (12 tau^2) = 0.08 % (docs/validation.md).
constexpr double vacf_step = 0.1;

/// The mean free time of the EDMD fluid at its start (sigma sqrt(m/kT), kT = 1), from
/// the Enskog collision frequency (granular/theory.hpp) with the contact value
/// chi = (1 - eta)^-D: exact in 1D (Tonks), and above the Carnahan-Starling (3D) and
/// Henderson (2D) values, so that the estimate errs short and the step small. Two masses:
/// the lighter one's speed.
double estimated_mean_free_time(const RunOptions& o) {
  const double eta = o.packing;
  const double chi = std::pow(1.0 - eta, -o.dim);
  const double speed = two_species(o) && o.mass_ratio < 1.0 ? 1.0 / std::sqrt(o.mass_ratio) : 1.0;
  return 1.0 / (granular::enskog_collision_frequency(o.dim, eta, chi) * speed);
}

/// Whether the VACF's step resolves its decay, from the run's mean free time.
bool resolved(double dt, const analysis::JsonObject& s) {
  const double tau = summary_number(s, "mean_free_time");
  return std::isfinite(tau) && tau > 0.0 && dt <= max_vacf_step * tau;
}

class VacfOutput final : public Output {
 public:
  explicit VacfOutput(const RunSetup& s)
      : recorder_(std::min<std::size_t>(static_cast<std::size_t>(s.options.n), vacf_particles)),
        equilibrium_(s.options.shear_rate == 0.0 && s.options.restitution == 1.0) {}

  Observer* fine() override { return &recorder_; }
  void save(checkpoint::Writer& w) const override { w(recorder_); }
  void load(checkpoint::Reader& r) override { r(recorder_); }
  void write(OutputDir& out) const override {
    if (recorder_.frames() >= 2) recorder_.write_csv(out.staged("vacf.csv").string());
  }
  void summarize(analysis::JsonObject& s) const override {
    // a self-diffusion coefficient is that of a gas in equilibrium: a sheared gas's MSD
    // grows with the flow (as t^3 along it), a cooling gas's VACF is not stationary
    const bool ok = equilibrium_ && recorder_.frames() >= 8 && recorder_.has_positions() &&
                    resolved(recorder_.dt(), s);
    s.emplace_back("vacf_dt", recorder_.dt());
    analysis::VacfRecorder::Diffusion d;  // NaN: not measured
    if (ok) d = recorder_.diffusion(summary_number(s, "mean_free_time"));
    s.emplace_back("diffusion_green_kubo", d.green_kubo);
    s.emplace_back("diffusion_green_kubo_error", d.error);
    s.emplace_back("diffusion_green_kubo_statistical_error", d.statistical_error);
    s.emplace_back("diffusion_green_kubo_truncation_error", d.truncation_error);
    s.emplace_back("diffusion_cut_time", d.cut_time);
    s.emplace_back("diffusion_einstein", d.einstein);
    s.emplace_back("diffusion_einstein_error", d.einstein_error);
    check_routes(s, "diffusion_green_kubo_route_difference_se", d.green_kubo, d.error,
                 d.einstein, d.einstein_error,
                 "self-diffusion by the VACF (Green-Kubo) and by the MSD (Einstein)");
  }
  void report(std::string& text, const analysis::JsonObject& s) const override {
    const double tau = summary_number(s, "mean_free_time");
    // no collisions (no finite mean free time): nothing to resolve, nothing to say
    if (recorder_.frames() < 2 || resolved(recorder_.dt(), s) || !std::isfinite(tau) ||
        !(tau > 0.0))
      return;
    text += fmt::format(
        "  diffusion_green_kubo not given: the VACF is sampled every {:.3g} mean free times, "
        "too coarse for its decay\n",
        recorder_.dt() / tau);
  }
  std::string_view plot() const override {
    return recorder_.frames() >= 2 ? embedded::plot_vacf_gp : std::string_view{};
  }

 private:
  analysis::VacfRecorder recorder_;
  bool equilibrium_;  ///< neither sheared nor granular
};

}  // namespace

namespace outputs {
constexpr std::string_view vacf_files[] = {"vacf.csv", "vacf.png"};
extern const OutputKind vacf{
    .name = "vacf",
    .wanted = [](const RunOptions&, registry::EngineKind e) { return e == registry::EngineKind::edmd; },
    .make = make_output<VacfOutput>,
    .files = vacf_files,
    // fine stops of about vacf_step estimated mean free times between the sampling instants
    .substeps = [](const RunOptions& o, const Schedule& sampling) -> std::uint64_t {
      const double h = vacf_step * estimated_mean_free_time(o);
      const double every = sampling.every();
      return every > h && std::isfinite(h) ? static_cast<std::uint64_t>(std::ceil(every / h)) : 1;
    }};
}

}  // namespace hypergas::cli
