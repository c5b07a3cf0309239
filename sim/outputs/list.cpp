// sim/outputs/list.cpp -- the outputs a run can have, in order (output.hpp). An output's
// file defines its OutputKind; its one line here makes runs use it.
#include <array>

#include "moments.hpp"
#include "output.hpp"
#include "plot_run_gp.hpp"  // generated from scripts/plot_run.gp

namespace hypergas::cli {

namespace outputs {
extern const OutputKind vacf, transport, helfand, structure;
}

namespace {
const std::array<const OutputKind*, 5> kinds = {
    &outputs::moments,    // moments.csv, speed_histogram.csv
    &outputs::vacf,       // vacf.csv (EDMD)
    &outputs::transport,  // transport.csv, correlations.csv (DSMC --transport)
    &outputs::helfand,    // transport.csv, correlations.csv (EDMD --transport)
    &outputs::structure,  // rdf.csv, structure_factor.csv (EDMD --structure)
};
}  // namespace

std::vector<std::unique_ptr<Output>> make_outputs(const RunSetup& setup) {
  std::vector<std::unique_ptr<Output>> out;
  for (const OutputKind* k : kinds)
    if (k->wanted(setup.options, setup.engine)) out.push_back(k->make(setup));
  return out;
}

std::string plot_script(const std::vector<std::unique_ptr<Output>>& outputs) {
  std::string script(embedded::plot_run_gp);
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
