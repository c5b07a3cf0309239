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
#include <cstdlib>
#include <filesystem>

#include <fmt/core.h>

#include "commands.hpp"
#include "engine_runs.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/error.hpp"
#include "hypergas/studies/gnuplot.hpp"
#include "hypergas/studies/replicas.hpp"
#include "output_dir.hpp"
#include "run_summary.hpp"

namespace hypergas::cli {


namespace {
/// A message of the EDMD --transport recorder in the command's terms: a recording too
/// short for two correlation windows, known only once the equilibration has measured the
/// mean free time tau, names the --until that holds them. The recorder's windows are
/// lag_count(--correlation-time, --correlation-dt) <= correlation-time / correlation-dt + 17
/// steps of correlation-dt tau (analysis/src/integrals.hpp); the end asked for adds 5 % for
/// a tau that moves with a longer equilibration, rounded up to two digits. Other messages
/// pass unchanged.
std::string in_options(const RunOptions& o, const std::string& what) {
  const std::string head = "helfand: the recording (", mark = "(the mean free time is ";
  const auto at = what.find(mark);
  if (!o.transport || what.rfind(head, 0) != 0 || at == std::string::npos) return what;
  const double tau = std::strtod(what.c_str() + at + mark.size(), nullptr);
  if (!(tau > 0.0) || !std::isfinite(tau)) return what;
  const double t0 = sampling_start(o);
  const double span =
      1.05 * 2.0 * (o.correlation_time + 17.0 * o.correlation_dt) * tau;  // time units
  // --equilibration given: it stays; otherwise sampling starts at until / 5
  double until = o.was_given("--equilibration") ? t0 + span : span / 0.8;
  const double unit = std::pow(10.0, std::floor(std::log10(until)) - 1.0);
  until = std::ceil(until / unit) * unit;
  return fmt::format("--transport: the recording from t = {} to --until {} ({} time units) is "
                     "shorter than two correlation windows of --correlation-time {} mean free "
                     "times (the mean free time is {:.4g}, so {:.4g} time units each); run "
                     "longer: --until {:.4g}",
                     t0, o.until, o.until - t0, o.correlation_time, tau,
                     o.correlation_time * tau, until);
}
}  // namespace

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
  RunRecord rec = [&] {
    try {
      return simulate(o, !quiet, ctx);
    } catch (const InvalidInput& e) {
      std::string said = in_options(o, e.what());
      if (said == e.what()) throw;
      throw InvalidInput(said);
    }
  }();
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
  check_declared_files(out.staged_names(), o);  // each file has its output
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
  if (edmd) {
    // an undefined Z (a sheared or granular gas: edmd::has_pressure_Z) has no error either
    const std::string z =
        std::isfinite(summary_number(summary, "Z"))
            ? fmt::format("Z = PV/NkT {} +- {}", f("Z"), f("Z_error"))
            : fmt::format("Z = PV/NkT undefined {}",
                          o.shear_rate != 0.0 ? "under shear" : "in a granular gas");
    // a cooling gas's rate is a mean over a changing state, without a block error
    const std::string rate =
        std::isfinite(summary_number(summary, "collision_rate_error"))
            ? fmt::format("{} +- {}", f("collision_rate"), f("collision_rate_error"))
            : fmt::format("{} (mean over the cooling)", f("collision_rate"));
    fmt::print("  packing {}, {}, collision rate {}, mean free time {}\n", f("packing"), z, rate,
               f("mean_free_time"));
  }
  std::string files;
  for (const auto& name : out.committed()) files += (files.empty() ? "" : ", ") + name;
  fmt::print("  wrote {}/: {}\n", out.dir().string(), files);
  if (o.json) fmt::print("{}\n", analysis::to_json(summary));
  return 0;
}

}  // namespace hypergas::cli
