// sim/outputs/granular.cpp -- the summary keys of a granular gas (--restitution < 1) from the
// moments output's rows (granular_summary.hpp: the cumulants of the scaled state, the
// cooling rate, Haff's t0 and the speed tail, each beside its first Sonine value), and in
// EDMD haff_t0_enskog: Haff's t0 of the Enskog gas at the initial temperature (sigma
// sqrt(m/kT0)), with the contact value of Henderson (2D) or Carnahan-Starling (3D) at the
// run's packing (null in other dimensions and for two species). A sheared granular gas
// has its steady state's keys from the shear output, which excludes this one.
#include <cmath>
#include <limits>

#include "../granular_summary.hpp"
#include "../run_summary.hpp"
#include "hypergas/dsmc/models.hpp"
#include "hypergas/granular/theory.hpp"
#include "moments.hpp"
#include "output.hpp"

namespace hypergas::cli {

namespace {

class GranularOutput final : public Output {
 public:
  explicit GranularOutput(const RunSetup& s)
      : moments_(*s.moments),
        dsmc_(s.engine == registry::EngineKind::dsmc),
        one_species_(!two_species(s.options)) {
    run_.dim = s.options.dim;
    run_.restitution = s.options.restitution;
    run_.driven = dsmc_ && s.options.drive != dsmc::Drive::none;
    // the hard-sphere kernel: rate ~ |g| and the hard-sphere scattering law
    const registry::ModelTraits m =
        registry::model_traits(s.options.model, s.options.vhs_exponent);
    run_.hard_spheres = !dsmc_ || (m.exponent == 1.0 && !m.isotropic_scattering);
  }

  void write(OutputDir&) const override {}
  void summarize(analysis::JsonObject& s) const override {
    add_granular_summary(s, moments_.recorder(), run_, dsmc_);
    if (dsmc_) return;
    const int D = run_.dim;
    double haff = std::numeric_limits<double>::quiet_NaN();
    if ((D == 2 || D == 3) && one_species_) {
      const double eta = summary_number(s, "packing");
      const double chi =
          D == 2 ? granular::chi_henderson(eta) : granular::chi_carnahan_starling(eta);
      const double a2 = granular::a2_hcs(run_.restitution, D);
      haff = granular::haff_t0(run_.restitution, D, a2) /
             granular::enskog_collision_frequency(D, eta, chi);
    }
    s.emplace_back("haff_t0_enskog", haff);
  }

 private:
  const MomentsOutput& moments_;
  GranularRun run_;
  bool dsmc_, one_species_;
};

}  // namespace

namespace outputs {
extern const OutputKind granular{
    .name = "granular",
    .wanted = [](const RunOptions& o, registry::EngineKind) { return o.restitution != 1.0; },
    .make = make_output<GranularOutput>};
}

}  // namespace hypergas::cli
