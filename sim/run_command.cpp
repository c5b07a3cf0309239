// sim/run_command.cpp -- `hypergas run`: one simulation, its files, its summary.
//
// Order of work: the options are already validated; the output folder is prepared (created,
// checked writable, staging folder made); the engine runs and the recorders write CSV into
// staging; summary.json and the PNG plots follow; only then are the files moved into
// place. Any exception before the commit leaves the folder as it was, except for the
// checkpoint (checkpoint.hgck, written atomically during the run), which a finished run
// removes.
#include <chrono>
#include <filesystem>

#include <fmt/core.h>

#include "commands.hpp"
#include "engine_runs.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/studies/gnuplot.hpp"
#include "hypergas/studies/replicas.hpp"
#include "output_dir.hpp"
#include "plot_scripts.hpp"

namespace hypergas::cli {


int run_command(const RunOptions& o, checkpoint::Reader* resume, bool quiet) {
  if (!studies::replica_root()) {  // an MPI rank other than 0: only replicas to run
    if (o.replicas > 1) {
      RunContext none;
      (void)simulate(o, false, none);
    }
    return 0;
  }
  OutputDir out(o.out);
  const bool edmd = o.engine_kind() == registry::EngineKind::edmd;
  RunContext ctx;
  // no checkpoint, not even at Ctrl-C, for --transport and --structure: their correlations
  // and frames are not saved, so a resumed run would report a part of the run as the whole
  if (o.replicas == 1 && !o.transport && !o.structure)
    ctx.checkpoints = Checkpointer(out.dir(), o.checkpoint_every, o.checkpoint_wall_seconds());
  ctx.resume = resume;
  // gnuplot starts now, so that its start overlaps the run (its script follows the CSVs)
  studies::GnuplotProcess plot(out.staging());
  RunRecord rec = simulate(o, !quiet, ctx);
  // CSV and plots first, so that summary.json can say how long they took (output_s).
  const auto t0 = std::chrono::steady_clock::now();
  rec.moments.write_moments_csv(out.staged("moments.csv").string());
  rec.moments.write_speed_histogram_csv(out.staged("speed_histogram.csv").string());
  if (rec.vacf && rec.vacf->frames() >= 2) rec.vacf->write_csv(out.staged("vacf.csv").string());
  if (rec.transport) {
    rec.transport->write_transport_csv(out.staged("transport.csv").string());
    rec.transport->write_correlations_csv(out.staged("correlations.csv").string());
  }
  if (rec.helfand) {
    rec.helfand->write_transport_csv(out.staged("transport.csv").string());
    rec.helfand->write_correlations_csv(out.staged("correlations.csv").string());
  }
  if (rec.structure) {
    rec.structure->write_rdf_csv(out.staged("rdf.csv").string());
    rec.structure->write_structure_factor_csv(out.staged("structure_factor.csv").string());
  }
  plot.finish(run_plot_script(rec.vacf && rec.vacf->frames() >= 2,
                              rec.transport ? 1 : rec.helfand ? 2 : 0, bool(rec.structure)));
  rec.summary.emplace_back(
      "output_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  const analysis::JsonObject& summary = rec.summary;
  analysis::write_json(out.staged("summary.json").string(), summary);
  out.commit();
  // The run is complete: its checkpoint would only continue a finished run (and a .tmp left
  // by a process killed while writing one is garbage).
  std::error_code ec;
  std::filesystem::remove(out.dir() / Checkpointer::file_name, ec);
  std::filesystem::remove(out.dir() / (std::string(Checkpointer::file_name) + ".tmp"), ec);

  if (quiet) return 0;
  const auto f = [&](const char* k) { return summary_field(summary, k); };
  fmt::print("{} D={} model={} n={} seed={}: {} collisions in {} s ({} collisions/s)\n",
             f("engine"), f("dim"), f("model"), f("n"), f("seed"), f("collisions"), f("wall_s"),
             f("collisions_per_s"));
  fmt::print("  final kurtosis_x {} (MB 3), KS p-value of speeds {}, energy drift {}, "
             "momentum drift {}\n",
             f("kurtosis_x"), f("ks_p_speed"), f("energy_rel_drift"), f("momentum_drift"));
  if (rec.transport)
    for (const auto& c : rec.transport->finish())
      fmt::print("  {} {:.5g} +- {:.2g} (reduced), first Sonine {:.5g}, ratio {:.5f} +- {:.5f}\n",
                 c.name, c.value, c.error, c.sonine, c.ratio, c.ratio_error);
  if (rec.helfand)
    for (const auto& c : rec.helfand->finish())
      fmt::print("  {} {:.5g} +- {:.2g}, over first Sonine {:.5f} +- {:.5f}, over Enskog "
                 "{:.5f} +- {:.5f}\n",
                 c.name, c.value, c.error, c.ratio, c.ratio_error, c.enskog_ratio,
                 c.enskog_ratio_error);
  if (rec.structure)
    fmt::print("  g(sigma+) {:.5g} +- {:.2g} from the rdf (contact theorem from Z: {})\n",
               rec.structure->finish().contact, rec.structure->finish().contact_error,
               f("contact_value_from_Z"));
  if (edmd)
    fmt::print("  packing {}, Z = PV/NkT {}, collision rate {}, mean free time {}\n",
               f("packing"), f("Z"), f("collision_rate"), f("mean_free_time"));
  std::string files;
  for (const auto& name : out.committed()) files += (files.empty() ? "" : ", ") + name;
  fmt::print("  wrote {}/: {}\n", out.dir().string(), files);
  if (o.json) fmt::print("{}\n", analysis::to_json(summary));
  return 0;
}

}  // namespace hypergas::cli
