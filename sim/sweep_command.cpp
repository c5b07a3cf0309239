// sim/sweep_command.cpp -- `hypergas sweep PLAN.toml --out DIR`: the cases of a plan
// (sweep/plan.hpp), each a `hypergas run` into DIR/cases/<id>/, over the MPI ranks when an
// MPI launcher started the command (sweep/ranks.hpp), gathered into DIR/sweep.csv
// (sweep/tables.hpp).
//
// Order of work: every rank reads the plan and validates every case; rank 0 then checks the
// folder (new, empty, or holding this same sweep), takes its lock and writes DIR/plan.toml;
// any failure so far writes nothing and exits 2 on every rank. Then the cases that are not
// finished run, one per free rank; rank 0 rewrites sweep.csv as each ends and plots at the
// end. A case is finished when its folder holds summary.json and no checkpoint (run commits
// summary.json last and removes its checkpoint after). A killed sweep continues with
// `hypergas sweep --resume DIR` (or the same command): finished cases are kept, the others
// continue from their checkpoints or start again, and since every case is a deterministic
// run, the files are those of a sweep never stopped.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/core.h>

#include "commands.hpp"
#include "engine_runs.hpp"
#include "hypergas/options/suggest.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/error.hpp"
#include "locked_dir.hpp"
#include "progress.hpp"
#include "run_driver.hpp"
#include "sweep/plan.hpp"
#include "sweep/tables.hpp"

namespace fs = std::filesystem;

namespace hypergas::cli {

namespace {

using sweep::Case;

std::string read_text(const fs::path& file, const std::string& what) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw InvalidInput(fmt::format("{} '{}' is not a readable file", what, file.string()));
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  if (!in && !in.eof()) throw InvalidInput(fmt::format("cannot read {} '{}'", what, file.string()));
  return ss.str();
}

/// The cases' options as `resume` would see them: equal lists mean the same sweep.
bool same_cases(const std::vector<Case>& a, const std::vector<Case>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (options::replay_arguments(a[i].options) != options::replay_arguments(b[i].options))
      return false;
  return true;
}

/// Rank 0's hold on the sweep folder: created if missing (and removed again if the sweep
/// cannot start), locked against a second sweep, with plan.toml written.
class SweepDir {
 public:
  SweepDir(const fs::path& dir, const std::string& plan_text, const std::vector<Case>& cases,
           const fs::path& plan_name) : dir_(dir) {
    std::error_code ec;
    const fs::path stored = dir / "plan.toml";
    if (fs::exists(fs::symlink_status(dir, ec))) {
      if (!fs::is_directory(dir, ec))
        throw InvalidInput(fmt::format("sweep folder '{}' exists and is not a folder",
                                       dir.string()));
      if (fs::exists(stored, ec)) {
        const std::string text = read_text(stored, "plan");
        const std::vector<Case> before =
            sweep::make_cases(sweep::parse_plan(text, stored.string()), dir);
        if (!same_cases(before, cases))
          throw InvalidInput(fmt::format(
              "sweep folder '{}' holds another sweep: its plan.toml makes other cases than {}; "
              "give another --out, or continue that sweep with `hypergas sweep --resume {}`",
              dir.string(), plan_name.string(), dir.string()));
        fresh_ = false;
      } else if (!fs::is_empty(dir, ec)) {
        throw InvalidInput(fmt::format(
            "sweep folder '{}' is not empty and holds no plan.toml: give a new or empty folder",
            dir.string()));
      }
    }
    folder_.open(dir, words);
    if (fresh_) {
      const fs::path tmp = dir / ".plan.toml.tmp";
      std::ofstream f(tmp, std::ios::binary);
      f << plan_text;
      f.close();
      if (!f || (fs::rename(tmp, stored, ec), ec)) {
        fs::remove(tmp, ec);
        folder_.unlock();
        folder_.remove_created();
        throw InvalidInput(fmt::format("sweep folder '{}' is not writable", dir.string()));
      }
    }
  }
  SweepDir(const SweepDir&) = delete;
  SweepDir& operator=(const SweepDir&) = delete;

 private:
  /// The sweep folder's words for LockedDir's failures.
  static std::string words(LockedDir::Failure f, const fs::path& dir, const fs::path& missing,
                           const std::string& why) {
    switch (f) {
      case LockedDir::Failure::cannot_create:
        return fmt::format("sweep folder '{}' cannot be created: {} ({})", dir.string(),
                           missing.string(), why);
      case LockedDir::Failure::not_a_folder:
        return fmt::format("sweep folder '{}' exists and is not a folder", dir.string());
      case LockedDir::Failure::busy:
        return fmt::format("sweep folder '{}' is in use by another hypergas sweep", dir.string());
      default:
        return fmt::format("sweep folder '{}' cannot be opened", dir.string());
    }
  }
  fs::path dir_;
  LockedDir folder_;  // created if missing (and removed again if the sweep cannot start)
  bool fresh_ = true;
};

/// Refuses a plan whose plot names no column of sweep.csv before any case runs: the keys
/// come from a pilot of the first case with at most 1000 particles, one replica, one thread,
/// and (without --transport, whose correlations need their span) until at most 1, sampled
/// and equilibrated by default over that span, which writes nothing; a case of the plan
/// writes the same keys.
void check_plot_key(const sweep::Plan& plan, RunOptions o) {
  if (o.init_file.empty()) o.n = std::min(o.n, 1000LL);  // an init file sets N
  o.replicas = 1;
  o.threads = 1;
  if (!o.transport) o.until = std::min(o.until, 1.0);
  o.every = 0.0;
  o.equilibration = 0.0;  // a given one may lie beyond the pilot's end
  const RunRecord rec = simulate(o, false);
  std::vector<std::string> keys;
  for (const auto& [k, v] : rec.summary) keys.push_back(k);
  keys = sweep::table_keys(keys);
  if (std::find(keys.begin(), keys.end(), plan.plot_y) == keys.end())
    throw InvalidInput(fmt::format("sweep: plot = \"{}\" is not a column of sweep.csv (a "
                                   "summary key of the cases){}",
                                   plan.plot_y, options::did_you_mean(plan.plot_y, keys, "\"")));
}

/// Runs case c in this process: from its checkpoint where it has one written by this build
/// for these options, else from the start.
void run_case(const Case& c) {
  const fs::path ck = fs::path(c.options.out) / Checkpointer::file_name;
  std::error_code ec;
  if (fs::exists(ck, ec)) {
    std::optional<checkpoint::Reader> in;
    try {
      in.emplace(ck.string());
      in->tag("hypergas-run");
      std::string id;
      std::vector<std::string> args;
      (*in)(id, args);
      long long init_frame = -1;
      std::string init_checksum;
      if (id == build_identity()) (*in)(init_frame, init_checksum);
      if (id != build_identity() || args != options::replay_arguments(c.options) ||
          init_frame != c.options.init_frame_read || init_checksum != c.options.init_checksum)
        in.reset();
    } catch (const std::exception&) {
      in.reset();
    }
    if (in) {
      run_command(c.options, &*in, true);
      return;
    }
    fmt::print(stderr, "hypergas sweep: case {}: its checkpoint is from another build or "
                       "unreadable; the case starts again\n", c.id);
  }
  run_command(c.options, nullptr, true);
}

/// After Ctrl-C (SIGINT/SIGTERM reach every rank): one message, then the job ends; mpirun
/// reports MPI_Abort's code as its own, 130 without MPI.
int interrupted_exit(const ranks::Session& session, const fs::path& dir) {
  if (session.rank() == 0)
    fmt::print(stderr, "hypergas: sweep interrupted; continue with: hypergas sweep --resume {}\n",
               dir.string());
  session.abort(130);
  return 130;
}

}  // namespace

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& o) {
  CLI::App* s = app.add_subcommand(
      "sweep",
      "run the cases of PLAN.toml (run options; [sweep]: swept lists or ranges, replicas, "
      "plot), each into DIR/cases/<id>, gathered into DIR/sweep.csv; under mpirun/srun the "
      "cases are spread over the ranks (docs/sweeps.md)");
  s->add_option("plan", o.plan, "the plan (TOML); with --resume it must make the same cases");
  s->add_option("--out,-o", o.out, "the sweep folder (new, empty, or holding this sweep)");
  s->add_option("--resume", o.resume,
                "continue the sweep in this folder (its plan.toml): finished cases are kept, "
                "the others continue from their checkpoints");
  s->add_flag("--json", o.json, "print the sweep's figures as one JSON object, the last stdout line");
  return s;
}

int sweep_command(const SweepOptions& opt, const ranks::Session& session) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const bool root = session.rank() == 0;

  // The plan and its cases, on every rank; the folder, on rank 0.
  fs::path dir;
  sweep::Plan plan;
  std::vector<Case> cases;
  std::optional<SweepDir> hold;
  std::string error;
  try {
    if (opt.resume.empty() && opt.plan.empty())
      throw InvalidInput("sweep: give a plan (hypergas sweep PLAN.toml --out DIR) or "
                         "--resume DIR");
    if (!opt.resume.empty() && !opt.out.empty() && fs::path(opt.out) != fs::path(opt.resume))
      throw InvalidInput("sweep: --out and --resume name different folders; give one");
    if (opt.resume.empty() && opt.out.empty())
      throw InvalidInput("sweep: --out DIR is required (the sweep folder)");
    dir = opt.resume.empty() ? fs::path(opt.out) : fs::path(opt.resume);
    fs::path plan_file = opt.plan;
    if (!opt.resume.empty()) {
      std::error_code ec;
      if (!fs::is_regular_file(dir / "plan.toml", ec))
        throw InvalidInput(fmt::format("sweep --resume: '{}' is not a sweep folder (no "
                                       "plan.toml)", dir.string()));
      if (plan_file.empty()) plan_file = dir / "plan.toml";
    }
    const std::string text = read_text(plan_file, "plan");
    plan = sweep::parse_plan(text, plan_file.string());
    cases = sweep::make_cases(plan, dir);
    if (root && !plan.plot_y.empty() && !cases.empty()) check_plot_key(plan, cases.front().options);
    if (root) hold.emplace(dir, text, cases, plan_file);
  } catch (const InvalidInput& e) {
    error = e.what();
  }
  if (!session.agree(error.empty())) {
    if (!error.empty() && root) fmt::print(stderr, "hypergas: {}\n", error);
    return 2;
  }

  // Rank 0: which cases are finished, and the tables of those.
  sweep::Tables tables(plan, cases, dir);
  std::vector<std::size_t> todo;
  std::size_t kept = 0, with_checkpoint = 0;
  if (root) {
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const fs::path folder = cases[i].options.out;
      std::error_code ec;
      const bool ck = fs::exists(folder / Checkpointer::file_name, ec);
      if (!ck && fs::exists(folder / "summary.json", ec)) {
        tables.add(i);
        ++kept;
      } else {
        todo.push_back(i);
        with_checkpoint += ck ? 1 : 0;
      }
    }
    tables.write();
  }

  std::size_t finished = kept, failed = 0;
  const auto work = [&](std::size_t i) {
    try {
      run_case(cases[i]);
      return true;
    } catch (const InvalidInput& e) {
      fmt::print(stderr, "hypergas sweep: case {} ({}) failed: {}\n", cases[i].id,
                 cases[i].label, e.what());
    } catch (const std::runtime_error& e) {
      fmt::print(stderr, "hypergas sweep: case {} ({}) failed: {}\n", cases[i].id,
                 cases[i].label, e.what());
    }
    return false;
  };
  const auto done = [&](std::size_t i, bool ok, int rank) {
    if (!ok) {
      ++failed;
      return;
    }
    ++finished;
    tables.add(i);
    tables.write();
    fmt::print(stderr, "[{}/{}] case {}{}{} done on rank {}\n", finished, cases.size(),
               cases[i].id, cases[i].label.empty() ? "" : " ", cases[i].label, rank);
  };
  ranks::DispatchStats stats;
  try {
    stats = ranks::dispatch(session, todo, work, done);
  } catch (const InterruptedWithCheckpoint&) {
    return interrupted_exit(session, dir);
  } catch (const Interrupted&) {
    return interrupted_exit(session, dir);
  } catch (const std::exception& e) {
    fmt::print(stderr, "hypergas: sweep: error: {}\n", e.what());
    session.abort(1);
    return 1;
  }
  if (!root) return 0;

  tables.write();
  const bool plotted = !plan.plot_y.empty() && tables.plot();
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  const double per_handout_ms = stats.requests ? 1e3 * stats.wait_s / stats.requests : 0.0;
  fmt::print("sweep {}: {} case{}: {} run now ({} from checkpoints), {} kept, {} failed; "
             "{} rank{}, {:.3g} s\n",
             dir.string(), cases.size(), cases.size() == 1 ? "" : "s", todo.size() - failed,
             with_checkpoint, kept, failed,
             session.size(), session.size() == 1 ? "" : "s", wall);
  if (stats.requests)
    fmt::print("  coordination: {:.3f} ms from request to next case (mean of {} requests)\n",
               per_handout_ms, stats.requests);
  fmt::print("  wrote {}/sweep.csv{}{}\n", dir.string(), plan.replicas > 1 ? ", groups.csv" : "",
             plotted ? ", sweep.png" : "");
  if (failed)
    fmt::print(stderr, "hypergas sweep: {} case{} failed (messages above); `hypergas sweep "
                       "--resume {}` runs them again\n",
               failed, failed == 1 ? "" : "s", dir.string());
  if (opt.json)
    fmt::print("{}\n", analysis::to_json(analysis::JsonObject{
                           {"cases", static_cast<std::int64_t>(cases.size())},
                           {"run", static_cast<std::int64_t>(todo.size() - failed)},
                           {"from_checkpoints", static_cast<std::int64_t>(with_checkpoint)},
                           {"kept", static_cast<std::int64_t>(kept)},
                           {"failed", static_cast<std::int64_t>(failed)},
                           {"ranks", std::int64_t{session.size()}},
                           {"wall_s", wall},
                           {"handed_out", static_cast<std::int64_t>(stats.handed_out)},
                           {"coordination_ms", per_handout_ms},
                       }));
  return failed ? 1 : 0;
}

}  // namespace hypergas::cli
