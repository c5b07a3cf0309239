// sim/outputs/list.cpp -- the outputs a run can have, in order (output.hpp). An output's
// file defines its OutputKind; its one line here makes runs use it.
#include <array>
#include <cmath>

#include <fmt/core.h>

#include "moments.hpp"
#include "output.hpp"
#include "../run_summary.hpp"
#include "plot_run_gp.hpp"  // generated from scripts/plot_run.gp

namespace hypergas::cli {

namespace outputs {
extern const OutputKind vacf, pressure, transport, helfand, structure, histograms, shear;
#ifdef HYPERGAS_H5MD
extern const OutputKind trajectory;
#endif
}

namespace {
const auto kinds = std::to_array<const OutputKind*>({
    &outputs::moments,    // moments.csv, speed_histogram.csv
    &outputs::vacf,       // vacf.csv (EDMD)
    &outputs::pressure,   // Z_error, collision_rate_error (elastic EDMD)
    &outputs::transport,  // transport.csv, correlations.csv (DSMC --transport)
    &outputs::helfand,    // transport.csv, correlations.csv (EDMD --transport)
    &outputs::structure,  // rdf.csv, structure_factor.csv (EDMD --structure)
    &outputs::histograms, // speed_histograms.csv (--histogram-every)
    &outputs::shear,      // pressure_tensor.csv, rheology.png (--shear-rate)
#ifdef HYPERGAS_H5MD
    &outputs::trajectory, // trajectory.h5 (--trajectory-every)
#endif
});
}  // namespace

std::vector<std::unique_ptr<Output>> make_outputs(const RunSetup& setup) {
  std::vector<std::unique_ptr<Output>> out;
  for (const OutputKind* k : kinds)
    if (k->wanted(setup.options, setup.engine)) out.push_back(k->make(setup));
  return out;
}

std::string plot_script(const std::vector<std::unique_ptr<Output>>& outputs,
                        const analysis::JsonObject& summary) {
  const auto text = [&](const char* k) { return summary_field(summary, k); };
  const auto number = [&](const char* k) { return summary_number(summary, k); };
  const bool edmd = text("engine") == "edmd";
  std::string script = fmt::format("run_title = \"{}, D = {}, N = {}, {}, seed {}\"\n",
                                   text("engine"), text("dim"), text("n"), text("model"),
                                   text("seed"));
  const double alpha = number("restitution");
  const bool granular = std::isfinite(alpha) && alpha < 1.0;
  script += fmt::format("granular = {}\n", granular ? 1 : 0);
  if (granular) {
    // Haff's law from theory where the summary has it (DSMC first Sonine, EDMD Enskog),
    // else the fitted t0; EDMD cools from the end of its elastic equilibration
    double t0 = number(edmd ? "haff_t0_enskog" : "haff_t0_sonine");
    if (!std::isfinite(t0)) t0 = number("haff_t0");
    const double from = edmd ? number("equilibration_time") : 0.0;
    script += fmt::format(
        "time_unit = \"{}\"\nhaff_from = {:.17g}\nhaff_t0 = {}\na2_sonine = {}\n",
        edmd ? "sigma sqrt(m/kT0)" : "mean collision times at T0", from,
        std::isfinite(t0) ? fmt::format("{:.17g}", t0) : "NaN",
        std::isfinite(number("a2_sonine")) ? fmt::format("{:.17g}", number("a2_sonine"))
                                           : "NaN");
  }
  script += embedded::plot_run_gp;
  for (const auto& o : outputs) script += o->plot();
  return script;
}

bool checkpointable(const RunOptions& o) {
  if (o.replicas != 1) return false;
  for (const OutputKind* k : kinds)
    if (k->wanted(o, o.engine_kind()) && !k->checkpointable) return false;
  return true;
}

}  // namespace hypergas::cli
