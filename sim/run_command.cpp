// sim/run_command.cpp -- `hypergas run`: one simulation, its files, its summary.
//
// Order of work: the options are already validated; the output folder is prepared (created,
// checked writable, staging folder made); the engine runs and the recorders write CSV into
// staging; summary.json and the PNG plots follow; only then are the files moved into
// place. Any exception before the commit leaves the folder as it was, except for the
// checkpoint (checkpoint.hgck, written atomically during the run), which a finished run
// removes. A run with --checkpoint-every or --checkpoint-wall keeps its final state as
// final.hgck, one of its files.
#include <chrono>
#include <cmath>
#include <filesystem>

#include <fmt/core.h>

#include "commands.hpp"
#include "engine_runs.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/studies/gnuplot.hpp"
#include "hypergas/studies/replicas.hpp"
#include "output_dir.hpp"
#include "run_summary.hpp"

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
  // no checkpoint, not even at Ctrl-C, for replicas or an output a checkpoint cannot hold
  if (checkpointable(o)) {
    ctx.checkpoints = Checkpointer(out.dir(), o.checkpoint_every, o.checkpoint_wall_seconds());
    // a run that asked for checkpoints keeps its final state, committed with its files:
    // `hypergas resume DIR --until T` continues it
    if (o.checkpoint_every > 0.0 || !o.checkpoint_wall.empty())
      ctx.checkpoints.keep_final(out.staged(Checkpointer::final_name));
  }
  ctx.resume = resume;
  // gnuplot starts now, so that its start overlaps the run (its script follows the CSVs)
  studies::GnuplotProcess plot(out.staging());
  RunRecord rec = simulate(o, !quiet, ctx);
  // CSV and plots first, so that summary.json can say how long they took (output_s).
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& output : rec.outputs) output->write(out);
  const std::string script = plot_script(rec.outputs, rec.summary);
  out.write("plot.gp", script);  // to draw the PNGs again, or otherwise: gnuplot plot.gp
  plot.finish(script);
  rec.summary.emplace_back(
      "output_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  const analysis::JsonObject& summary = rec.summary;
  for (const auto& kv : summary)  // a gas too small for the chi-square test
    if (kv.first == "chi2_p_speed" && std::isnan(summary_number(summary, kv.first)))
      fmt::print(stderr,
                 "hypergas: note: N = {} is too few for the chi-square test of the speeds (it "
                 "needs 5 expected counts in each of 3 groups): chi2_p_speed is empty in "
                 "moments.csv and null in summary.json\n",
                 o.n);
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
  const bool granular = o.restitution != 1.0;
  const char* not_mb = granular ? " (against MB: a cooling gas is not Maxwellian)" : "";
  if (o.replicas > 1)  // the replicas' mean +- standard error; the files are replica 0's
    fmt::print("  {} replicas, mean +- se: final kurtosis_x {} +- {} (MB 3), KS p-value of "
               "speeds {} +- {}{}; largest energy drift {}, momentum drift {}; the files are "
               "replica 0's\n",
               o.replicas, f("kurtosis_x_replica_mean"), f("kurtosis_x_replica_se"),
               f("ks_p_speed_replica_mean"), f("ks_p_speed_replica_se"), not_mb,
               f("energy_rel_drift"), f("momentum_drift"));
  else
    fmt::print("  final kurtosis_x {} +- {} (MB 3), KS p-value of speeds {}{}, energy drift {}, "
               "momentum drift {}\n",
               f("kurtosis_x"), f("kurtosis_x_error"), f("ks_p_speed"), not_mb,
               f("energy_rel_drift"), f("momentum_drift"));
  if (granular) {
    // the measurements of a cooling or driven gas beside first Sonine theory
    std::string g = fmt::format("  restitution {}: a2 {} +- {} (first Sonine {})",
                                f("restitution"), f("a2_mean"), f("a2_error"), f("a2_sonine"));
    if (summary_field(summary, "haff_t0") != "-") {
      g += fmt::format(", Haff's t0 {} +- {} ({} {})", f("haff_t0"), f("haff_t0_error"),
                       edmd ? "Enskog" : "first Sonine",
                       f(edmd ? "haff_t0_enskog" : "haff_t0_sonine"));
    }
    fmt::print("{}, T / T0 at the end {}\n", g, f("temperature_ratio"));
  }
  std::string lines;
  for (const auto& output : rec.outputs) output->report(lines, summary);
  fmt::print("{}", lines);
  if (edmd)
    fmt::print("  packing {}, Z = PV/NkT {} +- {}, collision rate {} +- {}, mean free time {}\n",
               f("packing"), f("Z"), f("Z_error"), f("collision_rate"),
               f("collision_rate_error"), f("mean_free_time"));
  std::string files;
  for (const auto& name : out.committed()) files += (files.empty() ? "" : ", ") + name;
  fmt::print("  wrote {}/: {}\n", out.dir().string(), files);
  if (o.json) fmt::print("{}\n", analysis::to_json(summary));
  return 0;
}

}  // namespace hypergas::cli
