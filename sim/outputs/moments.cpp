// sim/outputs/moments.cpp -- the moments output (moments.hpp).
#include "moments.hpp"

#include "../granular_summary.hpp"
#include "../output_dir.hpp"
#include "hypergas/dsmc/models.hpp"
#include "plot_moments_gp.hpp"  // generated from scripts/run/moments.gp

namespace hypergas::cli {

MomentsOutput::MomentsOutput(const RunSetup& s)
    : dim_(s.options.dim),
      dsmc_(s.engine == registry::EngineKind::dsmc),
      restitution_(s.options.restitution),
      driven_(dsmc_ && s.options.drive != dsmc::Drive::none),
      // the hard-sphere kernel: rate ~ |g| and the hard-sphere scattering law
      hard_spheres_(!dsmc_ || [&] {
        const registry::ModelTraits m =
            registry::model_traits(s.options.model, s.options.vhs_exponent);
        return m.exponent == 1.0 && !m.isotropic_scattering;
      }()),
      sheared_(dsmc_ && s.options.shear_rate != 0.0) {
  if (dsmc_) recorder_.set_threads(s.options.threads);
}

void MomentsOutput::write(OutputDir& out) const {
  recorder_.write_moments_csv(out.staged("moments.csv").string());
  recorder_.write_speed_histogram_csv(out.staged("speed_histogram.csv").string());
}

void MomentsOutput::summarize(analysis::JsonObject& s) const {
  // the final row's estimates, each mean with its standard error over the particles
  s.emplace_back("kurtosis_x", last("kurtosis_x"));
  s.emplace_back("kurtosis_x_error", last("kurtosis_x_err"));
  s.emplace_back("m4_ratio", last("m4_ratio"));
  s.emplace_back("m4_ratio_error", last("m4_ratio_err"));
  for (const char* key : {"l1_speed", "ks_p_speed", "chi2_p_speed"}) s.emplace_back(key, last(key));
  // a sheared granular gas has its steady state's keys from the shear output
  if (restitution_ != 1.0 && !sheared_)
    add_granular_summary(s, recorder_, GranularRun{dim_, restitution_, driven_, hard_spheres_},
                         dsmc_);
}

std::string_view MomentsOutput::plot() const { return embedded::plot_moments_gp; }

namespace outputs {
const OutputKind moments{
    "moments", [](const RunOptions&, registry::EngineKind) { return true; },
    make_output<MomentsOutput>};
}

}  // namespace hypergas::cli
