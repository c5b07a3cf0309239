// tests/cli/test_checkpoint.cpp -- checkpoint and resume: a run killed at any moment and
// resumed writes the same files, byte for byte, as the same run never interrupted.
//
// The kill test: for each engine configuration, a reference run with checkpoints; then the
// same run started and killed with SIGKILL, resumed (`hypergas resume DIR`), killed again,
// ..., and resumed a last time to its end. Every kill waits on a readiness signal, not on a
// guessed time: the process must first have written its own checkpoints (one or two, seeded,
// seen as a new inode/mtime of DIR/checkpoint.hgck), and the kill then lands a seeded random
// fraction of the interval between its last two checkpoints later, so anywhere in the
// computation or in the writing of the next checkpoint, but always with a checkpoint to
// resume from and stops still to go. A run that ends before its kill, or a final
// summary.json that does not count every resume, fails the test. moments.csv,
// speed_histogram.csv and vacf.csv must equal the reference's byte for byte, and so must
// every physics field of summary.json (all but the wall-clock and bookkeeping fields), and
// trajectory.h5 dataset by dataset (h5diff exit 0). Where
// the kill lands is random, the assertion is not: a correct program passes for every delay.
// Also: Ctrl-C writes a checkpoint and says how to resume; corrupted, truncated, foreign and
// other-format-version checkpoints are refused with exit code 2 and leave the folder as it
// was; a second process on a folder in use is refused.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "cli/run_cli.hpp"
#include "hypergas/checkpoint.hpp"

namespace {

using namespace cli_test;

const std::vector<std::string> compared = {"moments.csv", "speed_histogram.csv", "vacf.csv"};

/// The integer field `key` of summary.json (one object on one line), or -1 if absent.
long summary_int(const fs::path& file, const std::string& key) {
  const std::string text = slurp(file), k = "\"" + key + "\": ";
  const auto pos = text.find(k);
  if (pos == std::string::npos) return -1;
  return std::strtol(text.c_str() + pos + k.size(), nullptr, 10);
}

/// Waits while `c` runs until `count` new checkpoints have appeared at `ck` (a stamp other
/// than the last one seen, starting from `seen`). Returns the wall time between the last two
/// appearances (0 if count is 1), or -1 if the command ended or 300 s passed first.
double await_checkpoints(Child& c, const fs::path& ck, int count, FileStamp seen) {
  using Clock = std::chrono::steady_clock;
  std::vector<Clock::time_point> at;
  const bool ok = c.wait_until([&] {
    const FileStamp now = stamp(ck);
    if (now.exists() && !(now == seen)) {
      seen = now;
      at.push_back(Clock::now());
    }
    return static_cast<int>(at.size()) >= count;
  });
  if (!ok) return -1.0;
  return at.size() < 2 ? 0.0 : std::chrono::duration<double>(at.back() - at[at.size() - 2]).count();
}

/// The kill test for one configuration (see the file comment): `kills` SIGKILLs, each
/// followed by a resume.
void kill_and_resume(const std::vector<std::string>& run_args, std::uint64_t seed, int kills) {
  Scratch s("ckpt");
  std::vector<std::string> ref_args = {"run"};
  ref_args.insert(ref_args.end(), run_args.begin(), run_args.end());
  ref_args.insert(ref_args.end(), {"--out", "ref"});
  const Result ref = run(ref_args, s.path());
  INFO("reference: " << ref.err);
  REQUIRE(ref.code == 0);
  REQUIRE(!fs::exists(s.path() / "ref" / "checkpoint.hgck"));  // a finished run removes it
  // Each process below writes at most 3 checkpoints before its kill (two awaited, then at
  // most about one interval): the reference must write more than all of them together.
  const long ref_checkpoints = summary_int(s.path() / "ref" / "summary.json", "checkpoints");
  REQUIRE(ref_checkpoints > 3 * kills + 1);

  std::vector<std::string> fresh = {"run"};
  fresh.insert(fresh.end(), run_args.begin(), run_args.end());
  fresh.insert(fresh.end(), {"--out", "cut"});
  const std::vector<std::string> resume = {"resume", "cut"};
  const fs::path ck = s.path() / "cut" / "checkpoint.hgck";
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> awaited(1, 2);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  for (int attempt = 0; attempt < kills; ++attempt) {
    // The first process starts the run, every later one resumes the previous one's last
    // checkpoint.
    REQUIRE(fs::exists(ck) == (attempt > 0));
    Child c(attempt == 0 ? fresh : resume, s.path());
    const int count = awaited(rng);
    const double u = fraction(rng);
    const double gap = await_checkpoints(c, ck, count, stamp(ck));
    if (gap < 0.0) {
      const Result early = c.wait();
      FAIL("attempt " << attempt << " ended (exit code " << early.code << ") before writing "
                      << count << " checkpoint(s); the kill would come too late: "
                      << early.err);
    }
    // With one checkpoint awaited, the interval is not measured: kill at once.
    const bool alive = c.running_after(u * gap);
    c.signal(SIGKILL);
    const Result killed = c.wait();
    INFO("attempt " << attempt << " (" << count << " checkpoints, then " << u * gap
                    << " s): " << killed.err);
    REQUIRE(alive);  // else the run finished before the kill: it was not interrupted
    REQUIRE(killed.signal == SIGKILL);
  }
  const Result last = run(resume, s.path());
  INFO("final resume: " << last.err);
  REQUIRE(last.code == 0);
  // Every kill was followed by a resume, and the run's own bookkeeping says so.
  CHECK(summary_int(s.path() / "cut" / "summary.json", "resumes") == kills);
  CHECK(summary_int(s.path() / "cut" / "summary.json", "resumes") >= 1);
  for (const std::string& f : compared) {
    INFO(f);
    REQUIRE(fs::exists(s.path() / "ref" / f) == fs::exists(s.path() / "cut" / f));
    if (fs::exists(s.path() / "ref" / f))
      CHECK(slurp(s.path() / "ref" / f) == slurp(s.path() / "cut" / f));
  }
  CHECK(physics_summary(s.path() / "ref" / "summary.json") ==
        physics_summary(s.path() / "cut" / "summary.json"));
  // trajectory.h5 (--trajectory-every): HDF5 files are not byte-stable after a resize, so
  // the datasets and attributes are compared, by h5diff (hdf5-tools): exit 0 when equal
  REQUIRE(fs::exists(s.path() / "ref" / "trajectory.h5") ==
          fs::exists(s.path() / "cut" / "trajectory.h5"));
  if (fs::exists(s.path() / "ref" / "trajectory.h5")) {
    Spawn h5diff;
    h5diff.program = "/usr/bin/h5diff";
    const Result d = Child({"ref/trajectory.h5", "cut/trajectory.h5"}, s.path(), h5diff).wait();
    INFO("h5diff: " << d.out << d.err);
    CHECK(d.code == 0);
    CHECK(!fs::exists(s.path() / "cut" / "trajectory.h5.partial"));
  }
  CHECK(!fs::exists(s.path() / "cut" / "checkpoint.hgck"));
  CHECK(!fs::exists(s.path() / "cut" / "checkpoint.hgck.tmp"));
  for (const auto& e : fs::directory_iterator(s.path() / "cut"))
    CHECK(e.path().filename().string().rfind(".hypergas-staging", 0) != 0);
}

/// Starts `hypergas run args --out DIR` in `cwd` and sends Ctrl-C as soon as the run holds
/// its output folder (readiness: the staging folder exists, so the lock is taken and the
/// handler installed); the run then stops at its next stop with a checkpoint.
Result interrupt_when_started(std::vector<std::string> args, const fs::path& cwd,
                              const std::string& dir) {
  args.insert(args.end(), {"--out", dir});
  Child c(args, cwd);
  const bool started = c.wait_until([&] { return has_staging(cwd / dir); });
  c.signal(SIGINT);
  Result r = c.wait();
  if (!started) r.err = "(ended before its staging folder appeared) " + r.err;
  return r;
}

/// The folder's files: relative path -> content.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    m[e.path().lexically_relative(dir).string()] = e.is_regular_file() ? slurp(e.path()) : "/";
  return m;
}

std::vector<std::string> dsmc(int dim, const char* model, bool species) {
  std::vector<std::string> a = {"--engine", "dsmc", "--dim", std::to_string(dim), "--model",
                                model, "--n", "100000", "--until", "3", "--every", "0.05",
                                "--seed", "11", "--checkpoint-every", "0.2"};
  if (species) a.insert(a.end(), {"--mass-ratio", "3", "--fraction", "0.4"});
  return a;
}

std::vector<std::string> edmd(int dim, const char* packing, const char* n, bool species) {
  std::vector<std::string> a = {"--engine", "edmd", "--dim", std::to_string(dim), "--n", n,
                                "--packing", packing, "--until", "10", "--every", "0.1",
                                "--seed", "5", "--checkpoint-every", "0.5"};
  if (species) a.insert(a.end(), {"--mass-ratio", "2", "--fraction", "0.3"});
  return a;
}

}  // namespace

TEST_CASE("kill and resume: DSMC hard spheres in 3D continues byte for byte", "[checkpoint]") {
  kill_and_resume(dsmc(3, "hs", false), 1, 2);
}

TEST_CASE("kill and resume: EDMD in 3D continues byte for byte", "[checkpoint]") {
  kill_and_resume(edmd(3, "0.3", "2000", false), 2, 2);
  kill_and_resume(edmd(3, "0.45", "2000", false), 11, 2);  // the dense regime: lists
}

namespace {
/// `args` with `extra` appended.
std::vector<std::string> with(std::vector<std::string> args,
                              const std::vector<std::string>& extra) {
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}
}  // namespace

TEST_CASE("kill and resume: the trajectory continues dataset by dataset", "[checkpoint]") {
  // DSMC velocities every 0.2; EDMD positions, images, box and velocities every 0.5
  kill_and_resume(with(dsmc(3, "hs", false), {"--trajectory-every", "0.2"}), 21, 2);
  kill_and_resume(with(edmd(3, "0.3", "2000", false), {"--trajectory-every", "0.5"}), 22, 2);
}

TEST_CASE("kill and resume: granular gases continue byte for byte", "[checkpoint]") {
  // DSMC cooling gas: the scaled velocities with their real time, temperature and log scale
  kill_and_resume(with(dsmc(3, "hs", false), {"--restitution", "0.7"}), 12, 2);
  // DSMC driven gas: the kicks and their clock
  kill_and_resume(with(dsmc(3, "hs", false),
                       {"--restitution", "0.7", "--drive", "white-noise", "--drive-dt", "0.3"}),
                  13, 2);
  // EDMD: elastic until t = 2, then quenched to 0.8; the kills land before or after the
  // quench, and the TC model's last collision times are kept
  kill_and_resume(
      with(edmd(3, "0.3", "2000", false), {"--restitution", "0.8", "--tc-time", "0.01"}), 14, 2);
}

TEST_CASE("kill and resume: the lanes scheme continues byte for byte", "[checkpoint]") {
  // 25 lanes of 4000 with epochs of 0.7: kills land inside epochs and between them; the
  // resumed run takes its lanes on another number of threads
  kill_and_resume(with(dsmc(3, "hs", false),
                       {"--scheme", "lanes", "--lane-size", "4000", "--epoch", "0.7"}),
                  15, 2);
}

TEST_CASE("kill and resume: DSMC models, species and D = 1, 3, 6", "[checkpoint][long]") {
  kill_and_resume(dsmc(1, "hs", true), 3, 3);
  kill_and_resume(dsmc(3, "maxwell", false), 4, 3);
  kill_and_resume(dsmc(3, "vhs", true), 5, 3);
  kill_and_resume(dsmc(6, "hs", false), 6, 3);
  kill_and_resume(dsmc(6, "maxwell", true), 7, 3);
}

TEST_CASE("kill and resume: EDMD in D = 1, 3, 6 and two species", "[checkpoint][long]") {
  kill_and_resume(edmd(1, "0.5", "500", true), 8, 3);
  kill_and_resume(edmd(3, "0.3", "2000", true), 9, 3);
  kill_and_resume(edmd(6, "0.1", "1000", false), 10, 3);
}

TEST_CASE("Ctrl-C writes a checkpoint, says how to resume, and resume finishes the run",
          "[checkpoint]") {
  Scratch s("ctrlc");
  std::vector<std::string> args = {"run"};
  const auto base = dsmc(3, "hs", false);
  args.insert(args.end(), base.begin(), base.end());
  args.insert(args.end(), {"--out", "ref"});
  REQUIRE(run(args, s.path()).code == 0);
  args.back() = "cut";
  // Readiness: the run's first checkpoint (t = 0.2 of 3). Ctrl-C then stops it at its next
  // sampling time with a new checkpoint.
  Child c(args, s.path());
  const fs::path ck = s.path() / "cut" / "checkpoint.hgck";
  const bool ready = c.wait_until([&] { return fs::exists(ck); });
  const FileStamp first = stamp(ck);
  c.signal(SIGINT);
  const Result r = c.wait();
  INFO(r.err);
  REQUIRE(ready);  // else the run ended before its first checkpoint: nothing was interrupted
  REQUIRE(r.signal == 0);
  REQUIRE(r.code == 130);
  CHECK(r.err.find("interrupted at t = ") != std::string::npos);
  CHECK(r.err.find("hypergas resume cut") != std::string::npos);
  REQUIRE(fs::exists(ck));
  CHECK(!(stamp(ck) == first));  // the interrupt wrote its own checkpoint
  CHECK(!fs::exists(s.path() / "cut" / "moments.csv"));
  const Result done = run({"resume", "cut"}, s.path());
  INFO(done.err);
  REQUIRE(done.code == 0);
  CHECK(summary_int(s.path() / "cut" / "summary.json", "resumes") == 1);
  CHECK(slurp(s.path() / "ref" / "moments.csv") == slurp(s.path() / "cut" / "moments.csv"));
}

TEST_CASE("resume --until extends a finished run: the files of one run to the new end",
          "[checkpoint]") {
  // A run with --checkpoint-every keeps its final state (final.hgck); resume --until T goes
  // on from it. The reference is one run to T with the stopped run's sampling interval and,
  // for EDMD, its equilibration time, without checkpoints: every CSV file and the
  // physics of summary.json must be the same bytes.
  Scratch s("extend");
  const auto check_extension = [&](const std::vector<std::string>& first, const char* until,
                                   const std::vector<std::string>& reference,
                                   const std::vector<std::string>& files) {
    const auto run_ok = [&](std::vector<std::string> args, const char* folder) {
      if (folder) {
        args.insert(args.begin(), "run");
        args.insert(args.end(), {"--out", folder});
      }
      const Result r = run(args, s.path());
      INFO(args[0] << " " << args[1] << ": " << r.err);
      REQUIRE(r.code == 0);
    };
    run_ok(first, "ext");
    REQUIRE(fs::exists(s.path() / "ext" / "final.hgck"));
    run_ok({"resume", "ext", "--until", until}, nullptr);
    run_ok(reference, "ref");
    for (const std::string& f : files) {
      INFO(f);
      REQUIRE(fs::exists(s.path() / "ref" / f));
      CHECK(slurp(s.path() / "ref" / f) == slurp(s.path() / "ext" / f));
    }
    CHECK(physics_summary(s.path() / "ref" / "summary.json") ==
          physics_summary(s.path() / "ext" / "summary.json"));
    CHECK(summary_int(s.path() / "ext" / "summary.json", "resumes") == 1);
  };
  SECTION("DSMC") {
    check_extension({"--dim", "3", "--n", "3000", "--until", "4", "--every", "0.25", "--seed",
                     "3", "--init", "beams", "--checkpoint-every", "1", "--histogram-every",
                     "1"},
                    "7",
                    {"--dim", "3", "--n", "3000", "--until", "7", "--every", "0.25", "--seed",
                     "3", "--init", "beams", "--histogram-every", "1"},
                    {"moments.csv", "speed_histogram.csv", "speed_histograms.csv"});
  }
  SECTION("EDMD") {
    // sampled every (5 - 1) / 50 = 0.08 from t = 1: 9 = 1 + 100 intervals
    check_extension({"--engine", "edmd", "--dim", "3", "--n", "500", "--packing", "0.3",
                     "--until", "5", "--seed", "4", "--checkpoint-every", "2"},
                    "9",
                    {"--engine", "edmd", "--dim", "3", "--n", "500", "--packing", "0.3",
                     "--until", "9", "--every", "0.08", "--equilibration", "1", "--seed", "4"},
                    {"moments.csv", "speed_histogram.csv", "vacf.csv"});
    // a span that is not a whole number of intervals: refused, naming ends that are
    const Result bad = run({"resume", "ext", "--until", "9.3"}, s.path());
    CHECK(bad.code == 2);
    CHECK(bad.err.find("try --until 9.24 or ") != std::string::npos);
    // a finished run without --until, and an earlier end
    const Result plain = run({"resume", "ext"}, s.path());
    CHECK(plain.code == 2);
    CHECK(plain.err.find("is finished; `hypergas resume ext --until T`") != std::string::npos);
    const Result early = run({"resume", "ext", "--until", "3"}, s.path());
    CHECK(early.code == 2);
    CHECK(early.err.find("goes to 9 already") != std::string::npos);
  }
}

TEST_CASE("resume refuses corrupted, truncated, foreign and missing checkpoints",
          "[checkpoint]") {
  Scratch s("bad");
  const Result r = interrupt_when_started(
      {"run", "--engine", "dsmc", "--n", "300000", "--until", "5", "--every", "0.1"}, s.path(),
      "cut");
  INFO(r.err);
  REQUIRE(r.signal == 0);
  REQUIRE(r.code == 130);
  const fs::path ck = s.path() / "cut" / "checkpoint.hgck";
  REQUIRE(fs::exists(ck));
  const std::string good = slurp(ck);
  const auto write = [&](const std::string& bytes) {
    std::ofstream f(ck, std::ios::binary | std::ios::trunc);
    f << bytes;
  };
  const auto refused = [&](const char* what) {
    const auto before = contents(s.path() / "cut");
    const Result x = run({"resume", "cut"}, s.path());
    INFO(what << ": " << x.err);
    CHECK(x.code == 2);
    CHECK(x.err.rfind("hypergas: ", 0) == 0);
    CHECK(x.err.find("checkpoint") != std::string::npos);
    CHECK(lines(x.err).size() == 1);
    CHECK(contents(s.path() / "cut") == before);
  };
  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 0x10;
  write(flipped);
  refused("one bit flipped");
  write(good.substr(0, good.size() - 100));
  refused("truncated");
  write(good.substr(0, 10));
  refused("ten bytes");
  write("");
  refused("empty");
  write(std::string(4096, 'x'));
  refused("foreign");
  fs::remove(ck);
  refused("missing");
  write(good);
  const Result ok = run({"resume", "cut"}, s.path());
  INFO(ok.err);
  CHECK(ok.code == 0);
}

TEST_CASE("resume refuses a checkpoint of another format version and names both",
          "[checkpoint]") {
  namespace ckpt = hypergas::checkpoint;
  Scratch s("version");
  const Result r = interrupt_when_started(
      {"run", "--engine", "dsmc", "--n", "300000", "--until", "5", "--every", "0.1"}, s.path(),
      "cut");
  INFO(r.err);
  REQUIRE(r.code == 130);
  const fs::path ck = s.path() / "cut" / "checkpoint.hgck";
  REQUIRE(fs::exists(ck));
  const std::string good = slurp(ck);
  REQUIRE(good.size() > 40);
  std::uint32_t stored = 0;
  std::memcpy(&stored, good.data() + 8, 4);  // magic (8 bytes), then the version (u32)
  REQUIRE(stored == ckpt::format_version);
  REQUIRE(ckpt::format_version >= 3);  // raised on every layout change (docs/checkpoints.md)

  // The file with its version field set to `v`; with `rehash`, its checksum made valid again
  // (header without the size field, payload, size field: checkpoint.hpp), so that only the
  // version differs from a file this build would accept.
  const auto with_version = [&](std::uint32_t v, bool rehash) {
    std::string f = good;
    std::memcpy(f.data() + 8, &v, 4);
    if (rehash) {
      const std::size_t payload = f.size() - 24 - 16;
      ckpt::detail::WordHash h;
      const auto* p = reinterpret_cast<const unsigned char*>(f.data());
      h.add(p, 16);
      h.add(p + 24, payload);
      h.add(p + 16, 8);
      const std::uint64_t sum = h.finish();
      std::memcpy(f.data() + 24 + payload, &sum, 8);
    }
    return f;
  };
  // The rehashing is right: applied with the file's own version it gives the file back.
  REQUIRE(with_version(ckpt::format_version, true) == good);

  for (const std::uint32_t v : {1u, ckpt::format_version - 1, ckpt::format_version + 1}) {
    for (const bool rehash : {false, true}) {
      {
        std::ofstream f(ck, std::ios::binary | std::ios::trunc);
        f << with_version(v, rehash);
      }
      const auto before = contents(s.path() / "cut");
      const Result x = run({"resume", "cut"}, s.path());
      INFO("version " << v << (rehash ? ", checksum valid" : ", checksum stale") << ": "
                      << x.err);
      CHECK(x.code == 2);
      CHECK(x.err.rfind("hypergas: ", 0) == 0);
      CHECK(lines(x.err).size() == 1);
      CHECK(x.err.find("checkpoint format " + std::to_string(v) + ", this build reads format " +
                       std::to_string(ckpt::format_version)) != std::string::npos);
      CHECK(x.out.empty());
      CHECK(contents(s.path() / "cut") == before);  // nothing written, nothing removed
    }
  }
  // The same file with its own version is accepted and finishes the run.
  {
    std::ofstream f(ck, std::ios::binary | std::ios::trunc);
    f << good;
  }
  const Result ok = run({"resume", "cut"}, s.path());
  INFO(ok.err);
  CHECK(ok.code == 0);
}

TEST_CASE("a second process on a folder in use is refused", "[checkpoint]") {
  Scratch s("lock");
  fs::create_directories(s.path() / "other");
  // Readiness: the first run's staging folder, created right after it takes the folder's
  // lock. The run is far from its end (1000 time units) when the second process starts.
  Child first({"run", "--n", "300000", "--until", "1000", "--every", "0.5", "--out", "busy"},
              s.path());
  const bool holds = first.wait_until([&] { return has_staging(s.path() / "busy"); });
  const Result second =
      run({"run", "--n", "100", "--until", "0.5", "--out", "../busy"}, s.path() / "other");
  const bool still = first.running();
  first.signal(SIGINT);
  const Result r = first.wait();
  INFO("first: " << r.err << "\nsecond: " << second.err);
  REQUIRE(holds);
  REQUIRE(still);  // the folder was in use for the whole of the second process
  CHECK(second.code == 2);
  CHECK(second.err.find("in use by another hypergas process") != std::string::npos);
  CHECK(r.signal == 0);
  CHECK(r.code == 130);
}
