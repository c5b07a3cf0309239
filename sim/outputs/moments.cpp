// sim/outputs/moments.cpp -- the moments output (moments.hpp).
#include "moments.hpp"

#include "../output_dir.hpp"
#include "plot_moments_gp.hpp"  // generated from scripts/run/moments.gp

namespace hypergas::cli {

MomentsOutput::MomentsOutput(const RunSetup& s) {
  if (s.engine == registry::EngineKind::dsmc) recorder_.set_threads(s.options.threads);
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
}

std::string_view MomentsOutput::plot() const { return embedded::plot_moments_gp; }

namespace outputs {
constexpr std::string_view moments_files[] = {"moments.csv", "speed_histogram.csv", "moments.png",
                                             "cooling.png", "speed_histogram.png"};
const OutputKind moments{.name = "moments",
                         .wanted = [](const RunOptions&, registry::EngineKind) { return true; },
                         .make = make_output<MomentsOutput>,
                         .files = moments_files};
}

}  // namespace hypergas::cli
