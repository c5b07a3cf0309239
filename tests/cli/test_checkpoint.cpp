// tests/cli/test_checkpoint.cpp -- checkpoint and resume: a run killed at any moment and
// resumed writes the same files, byte for byte, as the same run never interrupted.
//
// The kill test: for each engine configuration, a reference run with checkpoints; then the
// same run started, killed with SIGKILL after a seeded random delay (uniform over the
// reference's wall time), resumed (`hypergas resume DIR`, or run again when the kill came
// before the first checkpoint), killed again, ..., until a process finishes. moments.csv,
// speed_histogram.csv and vacf.csv must equal the reference's byte for byte, and so must every
// physics field of summary.json (all but the wall-clock and bookkeeping fields). Where the kill
// lands is random, the assertion is not: a correct program passes for every delay. Also: Ctrl-C
// writes a checkpoint and says how to resume; corrupted, truncated and foreign checkpoints
// are refused with exit code 2.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "cli/run_cli.hpp"

namespace {

using namespace cli_test;

/// summary.json without the fields that measure the process rather than the physics.
std::string physics_summary(const fs::path& file) {
  static const std::vector<std::string> skip = {
      "\"wall_s\"",   "\"collisions_per_s\"", "\"engine_s\"",  "\"analysis_s\"",
      "\"checkpoints\"", "\"resumes\"",       "\"peak_rss_bytes_per_particle\"",
      "\"output_s\""};
  std::string text = slurp(file), out;
  // The file is one object on one line, pairs separated by `, "` (analysis/output.cpp).
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t next = text.find(", \"", pos);
    if (next == std::string::npos) next = text.size();
    const std::string pair = text.substr(pos, next - pos);
    const bool drop = std::any_of(skip.begin(), skip.end(), [&](const std::string& k) {
      return pair.find(k) != std::string::npos;
    });
    if (!drop) out += pair + "\n";
    pos = next + 2;
  }
  return out;
}

const std::vector<std::string> compared = {"moments.csv", "speed_histogram.csv", "vacf.csv"};

/// The kill test for one configuration (see the file comment). `kills` SIGKILLs at most.
void kill_and_resume(const std::vector<std::string>& run_args, std::uint64_t seed, int kills) {
  Scratch s("ckpt");
  std::vector<std::string> ref_args = {"run"};
  ref_args.insert(ref_args.end(), run_args.begin(), run_args.end());
  ref_args.insert(ref_args.end(), {"--out", "ref"});
  const auto t0 = std::chrono::steady_clock::now();
  const Result ref = run(ref_args, s.path());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO("reference: " << ref.err);
  REQUIRE(ref.code == 0);
  REQUIRE(!fs::exists(s.path() / "ref" / "checkpoint.hgck"));  // a finished run removes it

  std::vector<std::string> fresh = {"run"};
  fresh.insert(fresh.end(), run_args.begin(), run_args.end());
  fresh.insert(fresh.end(), {"--out", "cut"});
  const std::vector<std::string> resume = {"resume", "cut"};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> delay(0.05 * wall, 1.0 * wall);
  int killed = 0, resumed = 0;
  Result last;
  for (int attempt = 0; attempt < kills + 1; ++attempt) {
    const bool have = fs::exists(s.path() / "cut" / "checkpoint.hgck");
    const auto& args = have ? resume : fresh;
    resumed += have ? 1 : 0;
    last = attempt < kills ? run(args, s.path(), delay(rng), SIGKILL) : run(args, s.path());
    INFO("attempt " << attempt << ": " << last.err);
    if (last.code == 0) break;
    REQUIRE(last.code == 128 + SIGKILL);
    ++killed;
  }
  INFO("killed " << killed << " times, resumed " << resumed << " times: " << last.err);
  REQUIRE(last.code == 0);
  for (const std::string& f : compared) {
    INFO(f);
    REQUIRE(fs::exists(s.path() / "ref" / f) == fs::exists(s.path() / "cut" / f));
    if (fs::exists(s.path() / "ref" / f))
      CHECK(slurp(s.path() / "ref" / f) == slurp(s.path() / "cut" / f));
  }
  CHECK(physics_summary(s.path() / "ref" / "summary.json") ==
        physics_summary(s.path() / "cut" / "summary.json"));
  CHECK(!fs::exists(s.path() / "cut" / "checkpoint.hgck"));
  CHECK(!fs::exists(s.path() / "cut" / "checkpoint.hgck.tmp"));
  for (const auto& e : fs::directory_iterator(s.path() / "cut"))
    CHECK(e.path().filename().string().rfind(".hypergas-staging", 0) != 0);
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
  // Whenever SIGINT lands, the run stops at its next sampling time with a checkpoint.
  const Result r = run(args, s.path(), 0.3);
  if (r.code == 0) SUCCEED("the run finished before the interrupt");
  else {
    INFO(r.err);
    REQUIRE(r.code == 130);
    CHECK(r.err.find("hypergas resume cut") != std::string::npos);
    REQUIRE(fs::exists(s.path() / "cut" / "checkpoint.hgck"));
    const Result done = run({"resume", "cut"}, s.path());
    INFO(done.err);
    REQUIRE(done.code == 0);
  }
  CHECK(slurp(s.path() / "ref" / "moments.csv") == slurp(s.path() / "cut" / "moments.csv"));
}

TEST_CASE("resume refuses corrupted, truncated, foreign and missing checkpoints",
          "[checkpoint]") {
  Scratch s("bad");
  std::vector<std::string> args = {"run", "--engine", "dsmc", "--n", "300000", "--until", "5",
                                   "--every", "0.1", "--out", "cut"};
  // Ctrl-C early: the next stop writes the checkpoint.
  const Result r = run(args, s.path(), 0.15);
  INFO(r.err);
  REQUIRE(r.code == 130);  // the run takes seconds; the interrupt comes after 0.15 s
  const fs::path ck = s.path() / "cut" / "checkpoint.hgck";
  REQUIRE(fs::exists(ck));
  const std::string good = slurp(ck);
  const auto write = [&](const std::string& bytes) {
    std::ofstream f(ck, std::ios::binary | std::ios::trunc);
    f << bytes;
  };
  const auto refused = [&](const char* what) {
    const Result x = run({"resume", "cut"}, s.path());
    INFO(what << ": " << x.err);
    CHECK(x.code == 2);
    CHECK(x.err.rfind("hypergas: ", 0) == 0);
    CHECK(x.err.find("checkpoint") != std::string::npos);
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

TEST_CASE("a second process on a folder in use is refused", "[checkpoint]") {
  Scratch s("lock");
  fs::create_directories(s.path() / "other");
  Result first;
  // The first run takes seconds; Ctrl-C ends it after 2 s (with a checkpoint).
  std::thread t([&] {
    first = run({"run", "--n", "300000", "--until", "5", "--out", "busy"}, s.path(), 2.0);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const Result second =
      run({"run", "--n", "100", "--until", "0.5", "--out", "../busy"}, s.path() / "other");
  t.join();
  INFO("first: " << first.err << "\nsecond: " << second.err);
  CHECK(second.code == 2);
  CHECK(second.err.find("in use by another hypergas process") != std::string::npos);
  CHECK((first.code == 0 || first.code == 130));
}
