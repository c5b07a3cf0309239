// sim/resume_command.cpp -- `hypergas resume DIR [--until T]`: continues a stopped run from
// its checkpoint, or a finished one from the final state it kept.
//
// The checkpoint (run_driver.hpp, docs/checkpoints.md) starts with the build that wrote it and
// the run's arguments. The arguments are parsed and validated again exactly as `hypergas run`
// parses them, with --out DIR; the engine, the recorders and the loop's position are then
// restored and the run goes on, writing the same files a run that never stopped writes.
//
// With --until T the run goes on to T instead: its arguments get --until T, and --every
// (the interval the run sampled at) and, for EDMD, --equilibration (the time its sampling
// began), so that the continued run is the run to T with those options: its rows continue
// the stopped run's, and every file equals that run's bit for bit. A T whose span is not a
// whole number of the run's intervals is refused with the nearest ones that are.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <fmt/core.h>

#include "commands.hpp"
#include "engine_runs.hpp"
#include "hypergas/error.hpp"
#include "run_driver.hpp"

namespace hypergas::cli {

namespace {

void mark_given(RunOptions& o, const char* name) {
  if (!o.was_given(name)) o.given.emplace_back(name);
}

/// The options of the run continued to `until`: the same sampling instants up to the
/// stopped run's end (refused, naming the nearest ends that keep them, otherwise).
RunOptions extended(RunOptions o, double until) {
  if (!(until > 0.0) || !std::isfinite(until))
    throw InvalidInput(fmt::format("resume --until must be a finite time > 0, got {}", until));
  if (until < o.until)
    throw InvalidInput(fmt::format("resume --until {}: the run goes to {} already; give a later "
                                   "time",
                                   until, o.until));
  const double t0 = sampling_start(o);
  const Schedule old = o.schedule(t0);
  RunOptions x = o;
  x.until = until;
  x.every = old.every();
  mark_given(x, "--until");
  mark_given(x, "--every");
  if (o.engine_kind() == registry::EngineKind::edmd) {
    x.equilibration = t0;
    mark_given(x, "--equilibration");
  }
  // whether an end u keeps the stopped run's sampling instants
  const auto keeps = [&](double u) {
    RunOptions y = x;
    y.until = u;
    try {
      const Schedule s = y.schedule(t0);
      return s.every() == old.every() && s.time(old.intervals()) == old.until();
    } catch (const InvalidInput&) {
      return false;
    }
  };
  // an end near u as the fewest decimals that, read back as --until, keep the instants
  const auto text = [&](double u) {
    for (int d = 0; d <= 17; ++d) {
      const std::string t = fmt::format("{:.{}f}", u, d);
      const double v = std::strtod(t.c_str(), nullptr);
      if (std::abs(v - u) <= 1e-9 * std::abs(u) && v >= o.until && keeps(v)) return t;
    }
    return fmt::format("{}", u);
  };
  if (!keeps(until)) {
    const double k = std::floor((until - t0) / old.every());
    throw InvalidInput(fmt::format(
        "resume --until {}: the run sampled every {} from {}, and a span that is not a "
        "whole number of those intervals would move its rows; try --until {} or {}",
        until, old.every(), t0, text(t0 + k * old.every()), text(t0 + (k + 1.0) * old.every())));
  }
  validate(x);
  return x;
}

}  // namespace

CLI::App* add_resume_command(CLI::App& app, ResumeOptions& o) {
  CLI::App* r = app.add_subcommand(
      "resume", "continue a run stopped by Ctrl-C, a kill or a crash from DIR/checkpoint.hgck "
                "(written by run --checkpoint-every / --checkpoint-wall or at Ctrl-C); with "
                "--until, also a finished run from the final state it kept (DIR/final.hgck, "
                "written by a run with --checkpoint-every or --checkpoint-wall)");
  r->add_option("dir", o.dir, "the output folder of the stopped run")->required();
  r->add_option("--until", o.until,
                "go on to this later time (the run's time unit); the files are those of one "
                "run to this time with the run's sampling interval (--every) and, EDMD, its "
                "--equilibration");
  r->add_flag("--json", o.json, "print the summary as one JSON object, the last stdout line");
  return r;
}

int resume_command(const ResumeOptions& r) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(r.dir, ec))
    throw InvalidInput(fmt::format("resume: '{}' is not a folder", r.dir));
  const fs::path stopped = fs::path(r.dir) / Checkpointer::file_name;
  const fs::path final_state = fs::path(r.dir) / Checkpointer::final_name;
  const bool extend = r.until != 0.0;
  fs::path file = stopped;
  if (!fs::exists(stopped, ec)) {
    if (!fs::exists(final_state, ec))
      throw InvalidInput(fmt::format(
          "resume: '{}' holds no {} (a finished run removes its checkpoint) and no {} (kept "
          "by a run with --checkpoint-every or --checkpoint-wall)",
          r.dir, Checkpointer::file_name, Checkpointer::final_name));
    if (!extend)
      throw InvalidInput(fmt::format("resume: the run in '{}' is finished; `hypergas resume {} "
                                     "--until T` continues it to a later time T",
                                     r.dir, r.dir));
    file = final_state;
  }
  checkpoint::Reader in(file.string());
  in.tag("hypergas-run");
  std::string id;
  std::vector<std::string> args;
  in(id, args);
  if (id != build_identity())
    in.fail(fmt::format("written by '{}', this is '{}'; only the same build continues a run "
                        "bit for bit",
                        id, build_identity()));
  long long init_frame = -1;
  std::string init_checksum;
  in(init_frame, init_checksum);
  RunArgs a;
  CLI::App app{"hypergas run (from a checkpoint)"};
  add_run_options(app, a);
  args.push_back("--out");
  args.push_back(r.dir);
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11's order
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    in.fail(fmt::format("its run options do not parse: {}", e.what()));
  }
  RunOptions o = run_options(a);
  // the start the run had, even if --init-file has changed since: the engine's state comes
  // from the checkpoint
  o.init_frame_read = init_frame;
  o.init_checksum = init_checksum;
  if (extend) o = extended(std::move(o), r.until);
  o.json = r.json;
  return run_command(o, &in);
}

}  // namespace hypergas::cli
