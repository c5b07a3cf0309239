// sim/outputs/list.cpp -- the outputs a run can have, in order (output.hpp). An output's
// file defines its OutputKind; its one line here makes runs use it.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <fmt/core.h>

#include "moments.hpp"
#include "output.hpp"
#include "../run_summary.hpp"
#include "plot_run_gp.hpp"  // generated from scripts/plot_run.gp

namespace hypergas::cli {

namespace outputs {
extern const OutputKind granular, conservation, vacf, pressure, transport, helfand, structure,
    histograms, shear;
#ifdef HYPERGAS_H5MD
extern const OutputKind trajectory;
#endif
}

namespace {
const auto kinds = std::to_array<const OutputKind*>({
    &outputs::moments,      // moments.csv, speed_histogram.csv
    &outputs::granular,     // the granular keys (--restitution < 1)
    &outputs::conservation, // conservation.csv (elastic runs that conserve energy)
    &outputs::vacf,         // vacf.csv (EDMD)
    &outputs::pressure,     // Z_error, collision_rate_error (elastic EDMD)
    &outputs::transport,    // transport.csv, correlations.csv (DSMC --transport)
    &outputs::helfand,      // transport.csv, correlations.csv (EDMD --transport)
    &outputs::structure,    // rdf.csv, structure_factor.csv (EDMD --structure)
    &outputs::histograms,   // speed_histograms.csv (--histogram-every)
    &outputs::shear,        // pressure_tensor.csv, rheology.png (--shear-rate)
#ifdef HYPERGAS_H5MD
    &outputs::trajectory,   // trajectory.h5 (--trajectory-every)
#endif
});

/// The kinds a run has: those it wants, less those another wanted kind excludes.
std::vector<const OutputKind*> run_kinds(const RunOptions& o, registry::EngineKind engine) {
  std::vector<const OutputKind*> wanted;
  for (const OutputKind* k : kinds)
    if (k->wanted(o, engine)) wanted.push_back(k);
  std::vector<const OutputKind*> out;
  for (const OutputKind* k : wanted) {
    const bool excluded = std::any_of(wanted.begin(), wanted.end(), [&](const OutputKind* by) {
      return std::find(by->excludes.begin(), by->excludes.end(), k->name) != by->excludes.end();
    });
    if (!excluded) out.push_back(k);
  }
  return out;
}
}  // namespace

std::vector<std::unique_ptr<Output>> make_outputs(const RunSetup& setup) {
  std::vector<std::unique_ptr<Output>> out;
  RunSetup s = setup;
  for (const OutputKind* k : run_kinds(setup.options, setup.engine)) {
    out.push_back(k->make(s));
    if (k == &outputs::moments) s.moments = static_cast<const MomentsOutput*>(out.back().get());
  }
  return out;
}

std::uint64_t plan_substeps(const RunOptions& o, registry::EngineKind engine,
                            const Schedule& sampling) {
  std::uint64_t m = 1;
  for (const OutputKind* k : run_kinds(o, engine))
    if (k->substeps) m = std::max(m, k->substeps(o, sampling));
  return m;
}

bool partial_output_file(std::string_view name) {
  return std::any_of(kinds.begin(), kinds.end(), [&](const OutputKind* k) {
    return !k->partial.empty() && k->partial == name;
  });
}

void check_declared_files(const std::vector<std::string>& names, const RunOptions& o) {
  std::vector<std::string_view> declared{"summary.json", "plot.gp", Checkpointer::final_name};
  for (const OutputKind* k : run_kinds(o, o.engine_kind()))
    declared.insert(declared.end(), k->files.begin(), k->files.end());
  for (const std::string& n : names)
    if (std::find(declared.begin(), declared.end(), n) == declared.end())
      throw std::logic_error(fmt::format(
          "{}: a file that no output of the run declares (OutputKind::files)", n));
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
  const std::vector<const OutputKind*> ks = run_kinds(o, o.engine_kind());
  return std::all_of(ks.begin(), ks.end(), [](const OutputKind* k) { return k->checkpointable; });
}

}  // namespace hypergas::cli
