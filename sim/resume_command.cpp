// sim/resume_command.cpp -- `hypergas resume DIR`: continues a stopped run from its checkpoint.
//
// The checkpoint (run_driver.hpp, docs/checkpoints.md) starts with the build that wrote it and
// the run's arguments. The arguments are parsed and validated again exactly as `hypergas run`
// parses them, with --out DIR; the engine, the recorders and the loop's position are then
// restored and the run goes on, writing the same files a run that never stopped writes.
#include <CLI/CLI.hpp>
#include <filesystem>

#include <fmt/core.h>

#include "commands.hpp"
#include "hypergas/error.hpp"
#include "run_driver.hpp"

namespace hypergas::cli {

CLI::App* add_resume_command(CLI::App& app, ResumeOptions& o) {
  CLI::App* r = app.add_subcommand(
      "resume", "continue a run stopped by Ctrl-C, a kill or a crash from DIR/checkpoint.hgck "
                "(written by run --checkpoint-every / --checkpoint-wall or at Ctrl-C)");
  r->add_option("dir", o.dir, "the output folder of the stopped run")->required();
  r->add_flag("--json", o.json, "print the summary as one JSON object, the last stdout line");
  return r;
}

int resume_command(const ResumeOptions& r) {
  namespace fs = std::filesystem;
  const fs::path file = fs::path(r.dir) / Checkpointer::file_name;
  std::error_code ec;
  if (!fs::is_directory(r.dir, ec))
    throw InvalidInput(fmt::format("resume: '{}' is not a folder", r.dir));
  if (!fs::exists(file, ec))
    throw InvalidInput(fmt::format("resume: '{}' holds no {} (a finished run removes its "
                                   "checkpoint)",
                                   r.dir, Checkpointer::file_name));
  checkpoint::Reader in(file.string());
  in.tag("hypergas-run");
  std::string id;
  std::vector<std::string> args;
  in(id, args);
  if (id != build_identity())
    in.fail(fmt::format("written by '{}', this is '{}'; only the same build continues a run "
                        "bit for bit",
                        id, build_identity()));
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
  o.json = r.json;
  return run_command(o, &in);
}

}  // namespace hypergas::cli
