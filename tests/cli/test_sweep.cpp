// tests/cli/test_sweep.cpp -- `hypergas sweep PLAN.toml --out DIR`: a plan's cases run as
// `hypergas run` into DIR/cases/<id>/ and gathered into DIR/sweep.csv (and groups.csv, and
// sweep.png), in this process or spread over MPI ranks.
//
// The sweep folder depends on the plan alone: every file is byte for byte the same for any
// number of ranks and for a sweep killed (SIGKILL, the whole MPI job at once) and resumed,
// except summary.json's process fields (wall and stage times, speed, memory, checkpoint and
// resume counts), which are compared without them. The tests check:
// - the same files without MPI, under `mpirun -np 1` and under `mpirun -np 3`, and the case
//   order of sweep.csv (first swept key slowest, replica fastest, replica r's seed derived
//   from the plan's seed, replica 0 keeping it);
// - a killed sweep, resumed without MPI and under mpirun, keeps its finished cases untouched,
//   continues the cases that have checkpoints from them (their summary.json counts one
//   resume) and ends with the files of a sweep never stopped; its figures (--json) count
//   exactly the folder's state at the kill;
// - a bad plan or folder exits with code 2, one message naming the problem, nothing written;
// - 200 cases on 3 ranks: each runs exactly once (one row, one folder with its own seed, one
//   "done" line), on more than one rank (the cases are handed out while others run);
// - groups.csv holds each group's mean and standard error of its replicas' sweep.csv values,
//   and the values fixed within every group (dim, time, ...) once under their own names;
// - a case that fails at run time makes the sweep exit 1 with the other cases finished, and
//   --resume runs that case again.
// The MPI parts need the launcher found at configure time (HYPERGAS_MPIEXEC); without it
// they are skipped with a warning, and the rest runs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli/run_cli.hpp"

namespace {

using namespace cli_test;

#ifdef HYPERGAS_MPIEXEC
const std::string mpiexec = HYPERGAS_MPIEXEC;
#else
const std::string mpiexec;  // CMake found no MPI launcher: the MPI parts are skipped
#endif

const char* const no_mpi = "MPI launcher not found at configure time (HYPERGAS_MPIEXEC): "
                           "the MPI part of this test is skipped";

void write_file(const fs::path& file, const std::string& text) {
  std::ofstream f(file, std::ios::binary | std::ios::trunc);
  f << text;
}

/// `mpirun ... -np N hypergas args...`: more ranks than cores are allowed (--oversubscribe);
/// as root Open MPI needs --allow-run-as-root.
std::vector<std::string> under_mpi(int ranks, const std::vector<std::string>& args) {
  std::vector<std::string> a = {"--oversubscribe"};
  if (::geteuid() == 0) a.push_back("--allow-run-as-root");
  a.insert(a.end(), {"-np", std::to_string(ranks), HYPERGAS_CLI_PATH});
  a.insert(a.end(), args.begin(), args.end());
  return a;
}

/// Runs `hypergas args...` under `mpirun -np ranks` in `cwd` to its end.
Result run_mpi(int ranks, const std::vector<std::string>& args, const fs::path& cwd) {
  return Child(under_mpi(ranks, args), cwd, Spawn{mpiexec, false}).wait();
}

/// Every file and folder below `dir`: relative path -> content ("/" for a folder), with
/// summary.json files reduced to their physics fields and a case's final state (final.hgck,
/// which holds the wall-time counters of its loop) to its presence.
std::map<std::string, std::string> sweep_files(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = e.path().lexically_relative(dir).string();
    if (!e.is_regular_file()) m[rel] = "/";
    else if (e.path().filename() == "summary.json") m[rel] = physics_summary(e.path());
    else if (e.path().filename() == "final.hgck") m[rel] = "(the final state)";
    else m[rel] = slurp(e.path());
  }
  return m;
}

/// Every file and folder below `dir` with its full content: the state a refused command
/// must leave.
std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    m[e.path().lexically_relative(dir).string()] = e.is_regular_file() ? slurp(e.path()) : "/";
  return m;
}

/// Checks that sweep folder `b` holds the same files as `a`: the same names, the same bytes,
/// summary.json's physics fields the same.
void check_same_sweep(const fs::path& a, const fs::path& b) {
  const auto fa = sweep_files(a), fb = sweep_files(b);
  std::set<std::string> names;
  for (const auto& [k, v] : fa) names.insert(k);
  for (const auto& [k, v] : fb) names.insert(k);
  for (const std::string& k : names) {
    INFO(b.filename().string() << "/" << k << " against " << a.filename().string());
    REQUIRE(fa.count(k) == 1);
    REQUIRE(fb.count(k) == 1);
    CHECK(fa.at(k) == fb.at(k));
  }
}

/// Checks that a finished sweep folder holds no hidden file (staging folders, temporary
/// files, checkpoints): everything it wrote was committed or removed. The one hidden file
/// is each case folder's list of its files (.hypergas-files, sim/output_dir.hpp).
void check_clean(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    INFO(e.path().string());
    CHECK((name[0] != '.' || name == ".hypergas-files"));
    CHECK(name.find("checkpoint") == std::string::npos);
  }
}

/// The fields of one CSV line (RFC 4180 quoting; no line breaks inside fields).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> f(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') f.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else f.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      f.emplace_back();
    } else {
      f.back() += c;
    }
  }
  return f;
}

/// A CSV file: its header and rows, each row a map column -> field. Every row must have as
/// many fields as the header, and no column may be named twice (readers such as pandas
/// and hypergas.read_sweep need unique names).
struct Table {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
};

Table read_csv(const fs::path& file) {
  Table t;
  const std::vector<std::string> ls = lines(slurp(file));
  REQUIRE(!ls.empty());
  t.header = csv_fields(ls[0]);
  const std::set<std::string> names(t.header.begin(), t.header.end());
  INFO(file.string() << " header " << ls[0]);
  REQUIRE(names.size() == t.header.size());
  for (std::size_t i = 1; i < ls.size(); ++i) {
    const std::vector<std::string> f = csv_fields(ls[i]);
    INFO(file.string() << " line " << i + 1);
    REQUIRE(f.size() == t.header.size());
    std::map<std::string, std::string> row;
    for (std::size_t j = 0; j < f.size(); ++j) row.emplace(t.header[j], f[j]);
    t.rows.push_back(std::move(row));
  }
  return t;
}

/// The integer after `"key": ` in a one-line JSON object (summary.json, the --json line);
/// fails the test if absent.
long long json_int(const std::string& json, const std::string& key) {
  const std::string k = "\"" + key + "\": ";
  const auto pos = json.find(k);
  INFO("key " << key << " in " << json);
  REQUIRE(pos != std::string::npos);
  return std::strtoll(json.c_str() + pos + k.size(), nullptr, 10);
}

/// The last non-empty line of a text (--json prints its object last).
std::string last_line(const std::string& text) {
  const std::vector<std::string> ls = lines(text);
  for (auto it = ls.rbegin(); it != ls.rend(); ++it)
    if (!it->empty()) return *it;
  return {};
}

/// The id of case (or group) i of a sweep of fewer than 10000: "0003".
std::string case_id(std::size_t i) {
  char s[32];
  std::snprintf(s, sizeof s, "%04zu", i);
  return s;
}

std::string joined(const std::vector<std::string>& args) {
  std::string s;
  for (const std::string& a : args) s += (s.empty() ? "" : " ") + a;
  return s;
}

/// The state of a sweep's case folders as the command judges it: finished (summary.json and
/// no checkpoint), unfinished with a checkpoint, without summary.json.
struct CaseStates {
  std::size_t finished = 0, checkpointed = 0, without_summary = 0;
  std::vector<std::size_t> finished_ids, checkpointed_ids;
};

CaseStates case_states(const fs::path& dir, std::size_t count) {
  CaseStates s;
  for (std::size_t i = 0; i < count; ++i) {
    const fs::path c = dir / "cases" / case_id(i);
    std::error_code ec;
    const bool summary = fs::exists(c / "summary.json", ec);
    const bool ck = fs::exists(c / "checkpoint.hgck", ec);
    if (summary && !ck) s.finished_ids.push_back(i);
    if (ck) s.checkpointed_ids.push_back(i);
    s.without_summary += summary ? 0 : 1;
  }
  s.finished = s.finished_ids.size();
  s.checkpointed = s.checkpointed_ids.size();
  return s;
}

/// The plan of the first test: 2 x 3 swept values, 2 replicas, a plot: 12 small cases.
const char* const plan12 = R"(# twelve small DSMC cases
engine = "dsmc"
until = 2
seed = 3
[sweep]
dim = [2, 3]
n = [500, 1000, 1500]
replicas = 2
plot = "kurtosis_x"
plot_x = "n"
)";

}  // namespace

TEST_CASE("A sweep gives the same files without MPI, under mpirun -np 1 and -np 3", "[sweep]") {
  Scratch s("sweep-same");
  write_file(s.path() / "plan.toml", plan12);
  const Result plain = run({"sweep", "plan.toml", "--out", "plain"}, s.path());
  INFO("without MPI: " << plain.out << plain.err);
  REQUIRE(plain.code == 0);
  const fs::path dir = s.path() / "plain";
  CHECK(slurp(dir / "plan.toml") == plan12);
  check_clean(dir);

  // sweep.csv: 12 rows in case order, the first swept key slowest and the replica fastest;
  // replica 0 keeps the plan's seed, replica 1 gets one derived seed, the same in every group.
  const Table t = read_csv(dir / "sweep.csv");
  REQUIRE(t.rows.size() == 12);
  REQUIRE(t.header.size() > 5);
  CHECK(std::vector<std::string>(t.header.begin(), t.header.begin() + 5) ==
        std::vector<std::string>{"case", "dim", "n", "replica", "seed"});
  const std::vector<std::string> dims = {"2", "3"}, ns = {"500", "1000", "1500"};
  for (std::size_t i = 0; i < 12; ++i) {
    const auto& row = t.rows[i];
    INFO("row " << i);
    CHECK(row.at("case") == case_id(i));
    CHECK(row.at("dim") == dims[i / 6]);
    CHECK(row.at("n") == ns[(i / 2) % 3]);
    CHECK(row.at("replica") == std::to_string(i % 2));
    CHECK(row.at("seed") == (i % 2 == 0 ? "3" : t.rows[1].at("seed")));
    // the case's own summary.json says it ran with these options
    const std::string summary = slurp(dir / "cases" / case_id(i) / "summary.json");
    CHECK(std::to_string(json_int(summary, "dim")) == row.at("dim"));
    CHECK(std::to_string(json_int(summary, "n")) == row.at("n"));
  }
  CHECK(t.rows[1].at("seed") != "3");
  CHECK(t.header.end() == std::find(t.header.begin(), t.header.end(), "wall_s"));
  CHECK(read_csv(dir / "groups.csv").rows.size() == 6);

  if (mpiexec.empty()) {
    WARN(no_mpi);
    return;
  }
  for (const int ranks : {1, 3}) {
    const std::string out = "np" + std::to_string(ranks);
    const Result r = run_mpi(ranks, {"sweep", "plan.toml", "--out", out}, s.path());
    INFO("mpirun -np " << ranks << ": " << r.out << r.err);
    REQUIRE(r.code == 0);
    CHECK(r.out.find("12 cases: 12 run now (0 from checkpoints), 0 kept, 0 failed; " +
                     std::to_string(ranks) + (ranks == 1 ? " rank," : " ranks,")) !=
          std::string::npos);
    check_same_sweep(dir, s.path() / out);
  }
}

namespace {

/// The kill test's plan: 6 DSMC cases of about a second each, with a checkpoint every tenth
/// of a case, so that a case killed while running has checkpoints to continue from.
const char* const plan_kill = R"(engine = "dsmc"
dim = 3
until = 40
checkpoint_every = 4
seed = 21
[sweep]
n = [200000, 300000]
replicas = 3
)";
constexpr std::size_t kill_cases = 6;

/// Starts the sweep of plan.toml into `out` (under `mpirun -np 2` when MPI is there), in a
/// session of its own; once at least two cases are finished and an unfinished one has
/// written one to three of its ten checkpoints (so that it is far from its end and still
/// has a checkpoint when the kill lands), kills the whole job (the launcher, every rank and
/// what they started) with SIGKILL. Returns the case states right after the kill.
CaseStates start_and_kill(const fs::path& cwd, const std::string& out) {
  const std::vector<std::string> args = {"sweep", "plan.toml", "--out", out};
  std::optional<Child> c;
  if (mpiexec.empty()) c.emplace(args, cwd, Spawn{HYPERGAS_CLI_PATH, true});
  else c.emplace(under_mpi(2, args), cwd, Spawn{mpiexec, true});
  const fs::path dir = cwd / out;
  // per case: its last checkpoint seen (inode, mtime, size) and how many it has written
  std::vector<std::pair<FileStamp, int>> seen(kill_cases);
  const bool ready = c->wait_until([&] {
    bool early = false;
    for (std::size_t i = 0; i < kill_cases; ++i) {
      const fs::path folder = dir / "cases" / case_id(i);
      const FileStamp now = stamp(folder / "checkpoint.hgck");
      if (now.exists() && !(now == seen[i].first)) seen[i] = {now, seen[i].second + 1};
      early = early || (now.exists() && seen[i].second <= 3 &&
                        !fs::exists(folder / "summary.json"));
    }
    return early && case_states(dir, kill_cases).finished >= 2;
  });
  const bool gone = c->kill_session(SIGKILL);
  const Result r = c->wait();
  INFO("killed sweep: " << r.out << r.err);
  REQUIRE(ready);  // else the sweep ended before two cases finished and one checkpointed
  REQUIRE(gone);   // every process of the job ended
  CHECK(r.signal == SIGKILL);
  const CaseStates st = case_states(dir, kill_cases);
  REQUIRE(st.without_summary > 0);  // the sweep had not finished
  REQUIRE(st.finished >= 2);
  REQUIRE(st.checkpointed >= 1);
  return st;
}

/// Resumes the killed sweep in `out` with `hypergas sweep --resume out --json` (under
/// `mpirun -np ranks` if ranks > 0) and checks its figures and the folder against the
/// state at the kill and the reference sweep `ref`.
void resume_and_compare(const fs::path& cwd, const std::string& out, const CaseStates& killed,
                        int ranks, const fs::path& ref) {
  const fs::path dir = cwd / out;
  std::vector<FileStamp> kept;
  for (std::size_t i : killed.finished_ids)
    kept.push_back(stamp(dir / "cases" / case_id(i) / "summary.json"));
  const std::vector<std::string> args = {"sweep", "--resume", out, "--json"};
  const Result r = ranks > 0 ? run_mpi(ranks, args, cwd) : run(args, cwd);
  INFO("resume" << (ranks > 0 ? " under mpirun -np " + std::to_string(ranks) : "") << ": "
                << r.out << r.err);
  REQUIRE(r.code == 0);
  const std::string json = last_line(r.out);
  CHECK(json_int(json, "cases") == static_cast<long long>(kill_cases));
  CHECK(json_int(json, "kept") == static_cast<long long>(killed.finished));
  CHECK(json_int(json, "kept") > 0);
  CHECK(json_int(json, "from_checkpoints") == static_cast<long long>(killed.checkpointed));
  CHECK(json_int(json, "from_checkpoints") > 0);
  CHECK(json_int(json, "run") == static_cast<long long>(kill_cases - killed.finished));
  CHECK(json_int(json, "failed") == 0);
  CHECK(json_int(json, "ranks") == (ranks > 0 ? ranks : 1));
  // Finished cases are kept as they were; the checkpointed ones continued from their
  // checkpoint (their summary.json counts one resume), not from the start.
  for (std::size_t k = 0; k < kept.size(); ++k) {
    INFO("kept case " << case_id(killed.finished_ids[k]));
    CHECK(stamp(dir / "cases" / case_id(killed.finished_ids[k]) / "summary.json") == kept[k]);
  }
  for (std::size_t i : killed.checkpointed_ids) {
    INFO("checkpointed case " << case_id(i));
    CHECK(json_int(slurp(dir / "cases" / case_id(i) / "summary.json"), "resumes") == 1);
  }
  check_clean(dir);
  check_same_sweep(ref, dir);
}

}  // namespace

TEST_CASE("A sweep killed with SIGKILL (the whole mpirun job) and resumed gives the same files",
          "[sweep]") {
  Scratch s("sweep-kill");
  write_file(s.path() / "plan.toml", plan_kill);
  const Result ref = run({"sweep", "plan.toml", "--out", "ref"}, s.path());
  INFO("reference: " << ref.out << ref.err);
  REQUIRE(ref.code == 0);
  REQUIRE(read_csv(s.path() / "ref" / "sweep.csv").rows.size() == kill_cases);
  if (mpiexec.empty()) WARN(no_mpi << "; the sweep killed is the plain command");

  {  // killed (under mpirun -np 2 where MPI is there), resumed without MPI
    const CaseStates killed = start_and_kill(s.path(), "cut");
    resume_and_compare(s.path(), "cut", killed, 0, s.path() / "ref");
  }
  if (!mpiexec.empty()) {  // killed under mpirun -np 2, resumed under mpirun -np 3
    const CaseStates killed = start_and_kill(s.path(), "cut-mpi");
    resume_and_compare(s.path(), "cut-mpi", killed, 3, s.path() / "ref");
  }
}

namespace {

/// Runs `hypergas args...` in `s` (under `mpirun -np 3` with `mpi`) and checks that it is
/// refused: exit code 2, stderr names the problem (every one of `words`) on its first line
/// "hypergas: ...", and nothing below `s` changed (in particular the sweep folder `dir`,
/// when it did not exist, still does not).
void check_refused(const Scratch& s, const std::vector<std::string>& args, const fs::path& dir,
                   const std::vector<std::string>& words, bool mpi = false) {
  const auto before = tree(s.path());
  const std::size_t entries = s.entries();
  const bool existed = fs::exists(s.path() / dir);
  const Result r = mpi ? run_mpi(3, args, s.path()) : run(args, s.path());
  INFO((mpi ? "mpirun -np 3 " : "") << "hypergas " << joined(args)
                                    << "\nstdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.code == 2);
  if (!mpi) {
    CHECK(r.err.rfind("hypergas: ", 0) == 0);
    CHECK(lines(r.err).size() == 1);
    CHECK(r.out.empty());
  }
  // Under mpirun the launcher may add its own lines (its report, a network warning): the
  // command's message is its first line that starts with "hypergas: ".
  std::string first;
  for (const std::string& l : lines(r.err))
    if (l.rfind("hypergas: ", 0) == 0) {
      first = l;
      break;
    }
  CHECK(!first.empty());
  for (const std::string& w : words) {
    INFO("expected in the message: " << w);
    CHECK(first.find(w) != std::string::npos);
  }
  CHECK(s.entries() == entries);
  CHECK(tree(s.path()) == before);
  CHECK(fs::exists(s.path() / dir) == existed);
}

/// A plan of run options and a [sweep] table.
std::string plan(const std::string& fixed, const std::string& swept) {
  return fixed + "[sweep]\n" + swept;
}

}  // namespace

TEST_CASE("A bad plan writes nothing and exits 2, naming the problem", "[sweep]") {
  Scratch s("sweep-bad");
  const auto with_plan = [&](const std::string& text) { write_file(s.path() / "p.toml", text); };
  const std::vector<std::string> to_out = {"sweep", "p.toml", "--out", "out"};

  SECTION("a bad case: its id, values and option") {
    with_plan(plan("engine = \"edmd\"\ndim = 3\n", "packing = [0.1, 0.7]\n"));
    check_refused(s, to_out, "out", {"case 0001", "packing=0.7", "--packing"});
    if (mpiexec.empty()) {
      WARN(no_mpi);
    } else {  // every rank refuses, and the job exits 2
      check_refused(s, to_out, "out", {"case 0001", "--packing"}, true);
    }
  }
  SECTION("an unknown option key") {
    with_plan(plan("engine = \"dsmc\"\npakcing = 0.1\n", "n = [100, 200]\n"));
    check_refused(s, to_out, "out",
                  {"p.toml line 2", "unknown option 'pakcing'", "did you mean 'packing'?"});
  }
  SECTION("a run option in its command-line spelling") {
    with_plan(plan("engine = \"dsmc\"\nmass-ratio = 2\n", "n = [100, 200]\n"));
    check_refused(s, to_out, "out", {"unknown option 'mass-ratio'", "mass_ratio"});
  }
  SECTION("a duplicate case") {
    with_plan(plan("engine = \"edmd\"\n", "packing = [0.1, 0.1]\n"));
    check_refused(s, to_out, "out", {"case 0001", "repeats case 0000"});
  }
  SECTION("a folder that cannot be created") {
    with_plan(plan("engine = \"dsmc\"\n", "n = [100, 200]\n"));
    write_file(s.path() / "file", "a regular file, not a folder\n");
    check_refused(s, {"sweep", "p.toml", "--out", "file/sub"}, "file/sub",
                  {"sweep folder 'file/sub' cannot be created"});
    check_refused(s, {"sweep", "p.toml", "--out", "file/sub/deeper"}, "file/sub",
                  {"'file/sub/deeper' cannot be created"});
  }
  SECTION("a plot key that no case writes, before any case runs") {
    with_plan(plan("engine = \"dsmc\"\ndim = 3\nrestitution = 0.8\nuntil = 50\n",
                   "n = [1000, 2000]\nplot = \"a2_mena\"\n"));
    check_refused(s, to_out, "out",
                  {"plot = \"a2_mena\" is not a column of sweep.csv", "did you mean \"a2_mean\"?"});
    // a process measure is not a column either
    with_plan(plan("engine = \"dsmc\"\n", "n = [100, 200]\nplot = \"wall_s\"\n"));
    check_refused(s, to_out, "out", {"plot = \"wall_s\" is not a column of sweep.csv"});
    // the pilot's short span ignores an --equilibration beyond it: the plot key is judged
    with_plan(plan("engine = \"edmd\"\ndim = 3\nequilibration = 5\nuntil = 20\n",
                   "packing = [0.1, 0.2]\nplot = \"Zz\"\n"));
    check_refused(s, to_out, "out",
                  {"plot = \"Zz\" is not a column of sweep.csv", "did you mean \"Z\"?"});
  }
  SECTION("a TOML syntax error: its line") {
    with_plan("engine = \"dsmc\"\n\nn = = 3\n[sweep]\nseed = [1, 2]\n");
    check_refused(s, to_out, "out", {"p.toml line 3"});
  }
  SECTION("a key both fixed and swept") {
    with_plan(plan("engine = \"dsmc\"\nn = 100\n", "n = [100, 200]\n"));
    check_refused(s, to_out, "out", {"n is both fixed and swept"});
  }
  SECTION("--resume of a folder that is not a sweep") {
    fs::create_directories(s.path() / "plain");
    write_file(s.path() / "plain" / "notes.txt", "not a sweep\n");
    check_refused(s, {"sweep", "--resume", "plain"}, "plain",
                  {"'plain' is not a sweep folder"});
    check_refused(s, {"sweep", "--resume", "absent"}, "absent",
                  {"'absent' is not a sweep folder"});
  }
  SECTION("an existing non-empty folder without plan.toml") {
    with_plan(plan("engine = \"dsmc\"\n", "n = [100, 200]\n"));
    fs::create_directories(s.path() / "used");
    write_file(s.path() / "used" / "notes.txt", "something else\n");
    check_refused(s, {"sweep", "p.toml", "--out", "used"}, "used",
                  {"sweep folder 'used' is not empty and holds no plan.toml"});
  }
  SECTION("a different plan on an existing sweep folder") {
    with_plan(plan("engine = \"dsmc\"\ndim = 2\nuntil = 0.2\n", "n = [100, 200]\n"));
    const Result first = run(to_out, s.path());
    INFO(first.err);
    REQUIRE(first.code == 0);
    write_file(s.path() / "q.toml", plan("engine = \"dsmc\"\ndim = 2\nuntil = 0.2\n",
                                         "n = [100, 300]\n"));
    check_refused(s, {"sweep", "q.toml", "--out", "out"}, "out",
                  {"sweep folder 'out' holds another sweep", "q.toml"});
    check_refused(s, {"sweep", "q.toml", "--resume", "out"}, "out", {"holds another sweep"});
  }
}

TEST_CASE("200 tiny cases on 3 ranks: every case exactly once", "[sweep]") {
  if (mpiexec.empty()) {
    WARN(no_mpi);
    return;
  }
  Scratch s("sweep-200");
  write_file(s.path() / "plan.toml", plan("engine = \"dsmc\"\ndim = 2\nn = 50\nuntil = 0.2\n",
                                          "seed = { from = 1, to = 200, step = 1 }\n"));
  const Result r = run_mpi(3, {"sweep", "plan.toml", "--out", "out"}, s.path());
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find(": 200 cases: 200 run now (0 from checkpoints), 0 kept, 0 failed; 3 ranks") !=
        std::string::npos);

  // One row per case, in case order; each case's folder holds its own run (seed i + 1).
  const Table t = read_csv(s.path() / "out" / "sweep.csv");
  REQUIRE(t.rows.size() == 200);
  for (std::size_t i = 0; i < 200; ++i) {
    INFO("case " << case_id(i));
    CHECK(t.rows[i].at("case") == case_id(i));
    // the swept seed is the column plan_seed; seed is the case's own (equal: no replicas)
    CHECK(t.rows[i].at("plan_seed") == std::to_string(i + 1));
    CHECK(t.rows[i].at("seed") == std::to_string(i + 1));
    const fs::path summary = s.path() / "out" / "cases" / case_id(i) / "summary.json";
    REQUIRE(fs::exists(summary));
    CHECK(json_int(slurp(summary), "seed") == static_cast<long long>(i + 1));
  }

  // One "[k/200] case <id> seed=<v> done on rank R" line per case, k counting 1..200.
  // Searched, not matched whole: the cases' gnuplot processes share stderr and may write a
  // warning in pieces, so a piece of another process can precede the line.
  const std::regex done(R"(\[(\d+)/200\] case (\d{4}) seed=(\d+) done on rank (\d+)$)");
  std::map<std::string, int> per_case;
  std::set<int> ranks;
  int k = 0;
  for (const std::string& line : lines(r.err)) {
    std::smatch m;
    if (!std::regex_search(line, m, done)) continue;
    INFO(line);
    CHECK(std::stoi(m[1].str()) == ++k);
    CHECK(std::stoul(m[3].str()) == std::stoul(m[2].str()) + 1);
    ++per_case[m[2].str()];
    ranks.insert(std::stoi(m[4].str()));
  }
  CHECK(k == 200);
  CHECK(per_case.size() == 200);
  for (const auto& [id, count] : per_case) {
    INFO("case " << id);
    CHECK(count == 1);
  }
  CHECK(ranks.size() >= 2);  // handed out as ranks came free, not all run by one
  CHECK(*ranks.rbegin() <= 2);
}

TEST_CASE("groups.csv holds the mean and standard error of each group's replicas and its fixed "
          "options once",
          "[sweep]") {
  Scratch s("sweep-groups");
  write_file(s.path() / "plan.toml",
             plan("engine = \"dsmc\"\ndim = 2\nuntil = 1\nseed = 7\n",
                  "model = [\"hs\", \"maxwell\"]\nn = [300, 600]\nreplicas = 4\n"));
  const Result r = run({"sweep", "plan.toml", "--out", "out"}, s.path());
  INFO(r.out << r.err);
  REQUIRE(r.code == 0);
  const Table cases = read_csv(s.path() / "out" / "sweep.csv");
  const Table groups = read_csv(s.path() / "out" / "groups.csv");
  REQUIRE(cases.rows.size() == 16);
  REQUIRE(groups.rows.size() == 4);
  CHECK(std::vector<std::string>(groups.header.begin(), groups.header.begin() + 4) ==
        std::vector<std::string>{"group", "model", "n", "replicas"});
  CHECK(std::find(groups.header.begin(), groups.header.end(), "seed_mean") ==
        groups.header.end());
  // the options fixed in the plan appear once, as plain values, never averaged
  const auto has = [&](const std::string& h) {
    return std::find(groups.header.begin(), groups.header.end(), h) != groups.header.end();
  };
  for (const char* fixed : {"dim", "time"}) {
    CHECK(has(fixed));
    CHECK_FALSE(has(std::string(fixed) + "_mean"));
    CHECK_FALSE(has(std::string(fixed) + "_se"));
  }
  CHECK_FALSE(has("n_mean"));

  // Every <f>_mean / <f>_se pair against the mean and standard error (sample standard
  // deviation / sqrt(count)) of column f over the group's 4 rows of sweep.csv.
  std::vector<std::string> fields;
  for (const std::string& h : groups.header)
    if (h.size() > 5 && h.compare(h.size() - 5, 5, "_mean") == 0)
      fields.push_back(h.substr(0, h.size() - 5));
  CHECK(std::find(fields.begin(), fields.end(), "kurtosis_x") != fields.end());
  CHECK(std::find(fields.begin(), fields.end(), "collisions") != fields.end());
  const auto number = [](const std::string& text) {
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    INFO("'" << text << "'");
    REQUIRE(!text.empty());
    REQUIRE(*end == '\0');
    return x;
  };
  bool some_spread = false;
  std::map<std::string, bool> spread;  // per averaged field: some group's replicas differ
  for (std::size_t g = 0; g < 4; ++g) {
    const auto& row = groups.rows[g];
    INFO("group " << g);
    CHECK(row.at("group") == case_id(g));
    CHECK(row.at("replicas") == "4");
    for (std::size_t rep = 0; rep < 4; ++rep) {
      const auto& c = cases.rows[4 * g + rep];
      CHECK(c.at("model") == row.at("model"));
      CHECK(c.at("n") == row.at("n"));
      CHECK(c.at("replica") == std::to_string(rep));
      CHECK(c.at("dim") == "2");
      CHECK(c.at("dim") == row.at("dim"));
      CHECK(c.at("time") == row.at("time"));
    }
    for (const std::string& f : fields) {
      INFO("column " << f);
      std::vector<double> xs;
      for (std::size_t rep = 0; rep < 4; ++rep) xs.push_back(number(cases.rows[4 * g + rep].at(f)));
      double mean = 0.0;
      for (double x : xs) mean += x;
      mean /= 4.0;
      double ss = 0.0;
      for (double x : xs) ss += (x - mean) * (x - mean);
      const double se = std::sqrt(ss / 3.0 / 4.0);
      const double got_mean = number(row.at(f + "_mean")), got_se = number(row.at(f + "_se"));
      CHECK(std::fabs(got_mean - mean) <= 1e-12 * std::fabs(mean));
      // the standard error relative to itself, or to the mean where the replicas agree
      CHECK(std::fabs(got_se - se) <= 1e-12 * std::max(se, std::fabs(mean)));
      some_spread = some_spread || se > 0.0;
      spread[f] = spread[f] || xs[0] != xs[1] || xs[0] != xs[2] || xs[0] != xs[3];
    }
  }
  CHECK(some_spread);  // the replicas differ: the standard errors are not all zero
  // a field averaged in groups.csv is one whose replicas differ in some group
  for (const auto& [f, differs] : spread) {
    INFO("averaged column " << f);
    CHECK(differs);
  }
}

TEST_CASE("A case that fails at run time: exit 1, the others finish, --resume runs it again",
          "[sweep]") {
  // A finished sweep whose case 0001 folder is replaced by a regular file: the resumed sweep
  // runs case 0001 again, and its run fails (its output folder cannot be made) while the
  // plan is valid.
  Scratch s("sweep-fail");
  write_file(s.path() / "plan.toml", plan("engine = \"dsmc\"\ndim = 2\nuntil = 0.2\n",
                                          "n = [100, 200, 300]\n"));
  const Result first = run({"sweep", "plan.toml", "--out", "out"}, s.path());
  INFO(first.out << first.err);
  REQUIRE(first.code == 0);
  const fs::path dir = s.path() / "out";
  const std::string complete = slurp(dir / "sweep.csv");
  fs::remove_all(dir / "cases" / "0001");
  write_file(dir / "cases" / "0001", "in the way\n");

  const auto check_failed = [&](const Result& r, int ranks) {
    INFO((ranks > 0 ? "under mpirun: " : "") << r.out << r.err);
    CHECK(r.code == 1);
    CHECK(r.err.find("hypergas sweep: case 0001 (n=200) failed: ") != std::string::npos);
    const std::string json = last_line(r.out);
    CHECK(json_int(json, "kept") == 2);
    CHECK(json_int(json, "failed") == 1);
    CHECK(json_int(json, "run") == 0);
    // sweep.csv holds the finished cases only
    const Table t = read_csv(dir / "sweep.csv");
    REQUIRE(t.rows.size() == 2);
    CHECK(t.rows[0].at("case") == "0000");
    CHECK(t.rows[1].at("case") == "0002");
  };
  check_failed(run({"sweep", "--resume", "out", "--json"}, s.path()), 0);
  if (mpiexec.empty()) WARN(no_mpi);
  else check_failed(run_mpi(3, {"sweep", "--resume", "out", "--json"}, s.path()), 3);

  fs::remove(dir / "cases" / "0001");
  const Result again = run({"sweep", "--resume", "out", "--json"}, s.path());
  INFO(again.out << again.err);
  REQUIRE(again.code == 0);
  CHECK(json_int(last_line(again.out), "run") == 1);
  CHECK(json_int(last_line(again.out), "kept") == 2);
  CHECK(slurp(dir / "sweep.csv") == complete);
}

TEST_CASE("run --replicas under mpirun -np 2 writes the files of one process", "[sweep]") {
  // Replicas 1..3 run on whichever rank is free (ranks.hpp: ReplicaRanks) and only their
  // numbers travel to rank 0, which runs replica 0 and writes the files; each replica is a
  // pure function of its seed, so the files equal those of one process with 4 threads' worth
  // of replicas, and summary.json differs only in its process keys.
  if (mpiexec.empty()) {
    WARN(no_mpi);
    return;
  }
  Scratch s("sweep-replicas");
  const std::vector<std::string> args = {"run", "--dim", "3", "--n", "3000", "--until", "2",
                                         "--replicas", "5", "--seed", "11", "--out"};
  auto with_out = [&](const std::string& out) {
    std::vector<std::string> a = args;
    a.push_back(out);
    return a;
  };
  const Result one = run(with_out("one"), s.path());
  INFO(one.out << one.err);
  REQUIRE(one.code == 0);
  const Result two = run_mpi(2, with_out("two"), s.path());
  INFO(two.out << two.err);
  REQUIRE(two.code == 0);
  CHECK(!fs::exists(s.path() / "two" / "checkpoint.hgck"));
  for (const char* f : {"moments.csv", "speed_histogram.csv"})
    CHECK(slurp(s.path() / "one" / f) == slurp(s.path() / "two" / f));
  const std::string a = physics_summary(s.path() / "one" / "summary.json");
  CHECK(a.find("\"kurtosis_x_replica_se\"") != std::string::npos);
  CHECK(a == physics_summary(s.path() / "two" / "summary.json"));
}
