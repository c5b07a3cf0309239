// CLI tests: what a run records of its inputs and what it says about inputs it cannot take
// as given: the --init-file frame in summary.json and the checkpoint; a gas too small for
// the chi-square test; an EDMD --transport run too short; the sampling options that the
// span rounds (a note on stderr) or refuses (one line, exit 2); resume --until's suggested
// ends.
#include <catch2/catch.hpp>

#ifdef HYPERGAS_CLI_PATH
#include <cmath>
#include <cstdlib>

#include "cli/run_cli.hpp"

namespace {

using namespace cli_test;

/// The raw text of field `key` of summary.json (one object on one line): a number, null,
/// or a string with its quotes; "" if absent.
std::string field(const fs::path& file, const std::string& key) {
  const std::string text = slurp(file), k = "\"" + key + "\": ";
  const auto pos = text.find(k);
  if (pos == std::string::npos) return "";
  const std::size_t b = pos + k.size();
  std::size_t e = b;
  if (text[b] == '"') e = text.find('"', b + 1) + 1;
  else e = text.find_first_of(",}", b);
  return text.substr(b, e - b);
}

/// Runs `hypergas run args --out folder` in s; requires exit code 0.
Result run_ok(const Scratch& s, std::vector<std::string> args, const std::string& folder) {
  args.insert(args.begin(), "run");
  args.insert(args.end(), {"--out", folder});
  const Result r = run(args, s.path());
  INFO("run " << Catch::Detail::stringify(args) << ": " << r.err);
  REQUIRE(r.code == 0);
  return r;
}

/// Runs `hypergas run args --out <scratch>/out`: exit 2, one stderr line holding `part`,
/// nothing written.
void expect_rejected(std::vector<std::string> args, const std::string& part) {
  Scratch s("input-bad");
  args.insert(args.begin(), "run");
  args.insert(args.end(), {"--out", (s.path() / "out").string()});
  const Result r = run(args, s.path());
  INFO("args: " << Catch::Detail::stringify(args) << "\nstderr: " << r.err);
  CHECK(r.code == 2);
  CHECK(lines(r.err).size() == 1);
  CHECK(r.err.find(part) != std::string::npos);
  CHECK(r.out.empty());
  CHECK(s.entries() == 0);
}

/// The stderr lines of r that start with "hypergas: note: ".
std::vector<std::string> notes(const Result& r) {
  std::vector<std::string> v;
  for (const std::string& l : lines(r.err))
    if (l.rfind("hypergas: note: ", 0) == 0) v.push_back(l);
  return v;
}

/// The first column of a CSV file's rows (below the header).
std::vector<double> first_column(const fs::path& csv) {
  std::vector<double> t;
  const auto rows = lines(slurp(csv));
  for (std::size_t i = 1; i < rows.size(); ++i) t.push_back(std::strtod(rows[i].c_str(), nullptr));
  return t;
}

}  // namespace

TEST_CASE("run --init-file records the file, the frame read and its checksum", "[cli]") {
  Scratch s("init-record");
  // a DSMC trajectory: frames at t = 0, 1, 2 (velocities only)
  const Result made = run(std::vector<std::string>{"run", "--dim", "3", "--n", "200",
                                                   "--until", "2", "--every", "1",
                                                   "--trajectory-every", "1", "--init",
                                                   "maxwell", "--seed", "4", "--out", "a"},
                          s.path());
  if (made.code == 2 && made.err.find("needs HDF5") != std::string::npos) {
    WARN("this hypergas was built without HDF5: no --init-file");
    return;
  }
  REQUIRE(made.code == 0);
  const std::string file = (s.path() / "a" / "trajectory.h5").string();
  const std::vector<std::string> common = {"--until", "1", "--init-file", file};
  const auto from = [&](const char* frame, const char* folder) {
    std::vector<std::string> args = common;
    args.insert(args.end(), {"--init-frame", frame});
    run_ok(s, args, folder);
    return s.path() / folder / "summary.json";
  };
  const fs::path f0 = from("0", "f0"), f1 = from("1", "f1"), back = from("-2", "back"),
                 f2 = from("2", "f2");
  CHECK(field(f0, "init") == "\"file\"");
  CHECK(field(f0, "init_file") == "\"" + file + "\"");
  CHECK(field(f0, "init_frame") == "0");
  CHECK(field(f1, "init_frame") == "1");
  CHECK(field(back, "init_frame") == "1");  // -2 of three frames: the middle one
  CHECK(field(f2, "init_frame") == "2");
  const std::string c0 = field(f0, "init_checksum"), c1 = field(f1, "init_checksum"),
                    c2 = field(f2, "init_checksum");
  REQUIRE(c0.size() == 18);  // 16 hex digits and the quotes
  CHECK(c0.find_first_not_of("\"0123456789abcdef") == std::string::npos);
  CHECK(c0 != c1);
  CHECK(c1 != c2);
  CHECK(c0 != c2);
  CHECK(field(back, "init_checksum") == c1);  // the same frame, the same checksum
  // a generated start has none of these keys
  run_ok(s, {"--dim", "3", "--n", "200", "--until", "1"}, "gen");
  CHECK(field(s.path() / "gen" / "summary.json", "init") == "\"delta\"");
  CHECK(field(s.path() / "gen" / "summary.json", "init_checksum").empty());

  SECTION("a resumed run keeps the start's record from its checkpoint") {
    std::vector<std::string> args = common;
    args.insert(args.end(), {"--init-frame", "1", "--checkpoint-every", "0.5"});
    run_ok(s, args, "ck");
    // the file changes (frame 1 becomes frame 0's state): the run's start does not
    run_ok(s, {"--dim", "3", "--n", "200", "--until", "2", "--every", "1", "--trajectory-every",
               "1", "--init", "maxwell", "--seed", "5"},
           "other");
    fs::copy_file(s.path() / "other" / "trajectory.h5", file, fs::copy_options::overwrite_existing);
    const Result r = run(std::vector<std::string>{"resume", "ck", "--until", "2"}, s.path());
    INFO(r.err);
    REQUIRE(r.code == 0);
    const fs::path ck = s.path() / "ck" / "summary.json";
    CHECK(field(ck, "resumes") == "1");
    CHECK(field(ck, "init") == "\"file\"");
    CHECK(field(ck, "init_frame") == "1");
    CHECK(field(ck, "init_checksum") == c1);
  }
}

TEST_CASE("run with too few particles for the chi-square test: runs, p-value empty, a note",
          "[cli]") {
  Scratch s("small-n");
  for (const char* engine : {"dsmc", "edmd"})
    for (const char* n : {"2", "10"}) {
      const std::string folder = std::string(engine) + n;
      const Result r = run_ok(s, {"--engine", engine, "--dim", "3", "--n", n, "--until", "2"},
                              folder);
      INFO(engine << " N = " << n << ": " << r.err);
      const auto v = notes(r);
      CHECK(std::count_if(v.begin(), v.end(), [](const std::string& l) {
              return l.find("too few for the chi-square test") != std::string::npos;
            }) == 1);
      const fs::path dir = s.path() / folder;
      CHECK(field(dir / "summary.json", "chi2_p_speed") == "null");
      const std::string ks = field(dir / "summary.json", "ks_p_speed");
      CHECK((!ks.empty() && ks != "null"));  // the KS test needs no minimum
      // moments.csv: every row has the header's columns, chi2_p_speed empty
      const auto rows = lines(slurp(dir / "moments.csv"));
      REQUIRE(rows.size() == 52);
      const auto cols = [](const std::string& l) { return std::count(l.begin(), l.end(), ','); };
      const auto header = rows[0];
      std::size_t col = 0;
      for (std::size_t p = 0, k = 0; p < header.size(); ++k) {
        const std::size_t e = std::min(header.find(',', p), header.size());
        if (header.substr(p, e - p) == "chi2_p_speed") col = k;
        p = e + 1;
      }
      REQUIRE(col > 0);
      for (std::size_t i = 1; i < rows.size(); ++i) {
        CHECK(cols(rows[i]) == cols(header));
        std::size_t p = 0;
        for (std::size_t k = 0; k < col; ++k) p = rows[i].find(',', p) + 1;
        CHECK((rows[i][p] == ',' || p == rows[i].size()));  // the field is empty
      }
    }
  // enough particles: a p-value and no note
  const Result r = run_ok(s, {"--dim", "3", "--n", "1000", "--until", "2"}, "big");
  CHECK(notes(r).empty());
  const std::string p = field(s.path() / "big" / "summary.json", "chi2_p_speed");
  CHECK((!p.empty() && p != "null"));
}

TEST_CASE("run --every longer than the span: one interval, said on stderr", "[cli]") {
  Scratch s("every-long");
  const Result r = run_ok(s, {"--dim", "3", "--n", "500", "--until", "2", "--every", "100"}, "o");
  const auto v = notes(r);
  REQUIRE(v.size() == 1);
  CHECK(v[0] == "hypergas: note: --every 100 is longer than the sampled span 2: one interval, "
                "rows at t = 0 and 2 only");
  CHECK(first_column(s.path() / "o" / "moments.csv") == std::vector<double>{0.0, 2.0});
  // an --every within the span is rounded as documented, without a note
  CHECK(notes(run_ok(s, {"--dim", "3", "--n", "500", "--until", "2", "--every", "0.3"}, "p"))
            .empty());
}

TEST_CASE("run --scheme ntc with --dt longer than the sampling interval is refused", "[cli]") {
  expect_rejected({"--scheme", "ntc", "--dt", "5", "--until", "2"},
                  "hypergas: --dt 5 is longer than the sampling interval 0.04 (--until 2 in 50 "
                  "intervals)");
  expect_rejected({"--scheme", "ntc", "--dt", "0.5", "--until", "10", "--every", "0.25"},
                  "--dt 0.5 is longer than the sampling interval 0.25");
  Scratch s("ntc-ok");
  run_ok(s, {"--scheme", "ntc", "--dt", "0.04", "--until", "2", "--n", "500", "--dim", "3"}, "o");
}

TEST_CASE("run --mass-ratio with a --fraction that gives no second species is refused",
          "[cli]") {
  expect_rejected({"--mass-ratio", "2", "--fraction", "0"},
                  "--mass-ratio 2 with --fraction 0 and --n 10000: round(fraction N) = 0");
  expect_rejected({"--mass-ratio", "2", "--fraction", "0.0004", "--n", "1000"},
                  "round(fraction N) = 0 of the N particles");
  expect_rejected({"--mass-ratio", "2", "--fraction", "1", "--n", "1000"},
                  "round(fraction N) = 1000 of the N particles");
  expect_rejected({"--engine", "edmd", "--mass-ratio", "3", "--fraction", "0"},
                  "--mass-ratio 3 with --fraction 0");
  Scratch s("one-heavy");
  run_ok(s, {"--dim", "3", "--mass-ratio", "2", "--fraction", "0.002", "--n", "1000", "--until",
             "1"},
         "o");
}

TEST_CASE("run --trajectory-every and --histogram-every say the spacing they get", "[cli]") {
  Scratch s("series");
  // EDMD: sampling from t = 1 (until / 5) every 0.08; 1 / 0.08 = 12.5 rounds to 13
  const Result r = run(std::vector<std::string>{"run", "--engine", "edmd", "--dim", "3", "--n",
                                                "256", "--packing", "0.1", "--until", "5",
                                                "--histogram-every", "1", "--out", "e"},
                       s.path());
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto v = notes(r);
  REQUIRE(v.size() == 1);
  CHECK(v[0] == "hypergas: note: --histogram-every 1: histograms every 1.04 (13 sampling "
                "intervals of 0.08) from t = 1, the last at t = 4.12, not at --until 5; "
                "--every 0.0769231 gives histograms every 1 up to --until");
  // the frames are where the note says
  const auto t = first_column(s.path() / "e" / "speed_histograms.csv");
  REQUIRE(!t.empty());
  CHECK(std::abs(t.back() - 4.12) < 1e-9);
  // the advice holds: frames 1 apart, the last at --until, and no note
  const Result ok = run_ok(s, {"--engine", "edmd", "--dim", "3", "--n", "256", "--packing", "0.1",
                               "--until", "5", "--every", "0.0769231", "--histogram-every", "1"},
                           "f");
  CHECK(notes(ok).empty());
  const auto u = first_column(s.path() / "f" / "speed_histograms.csv");
  REQUIRE(!u.empty());
  CHECK(std::abs(u.back() - 5.0) < 1e-9);
  // DSMC from t = 0: every 0.04, 0.5 = 12.5 intervals
  const Result d = run_ok(s, {"--dim", "3", "--n", "500", "--until", "2", "--histogram-every",
                              "0.5"},
                          "d");
  REQUIRE(notes(d).size() == 1);
  CHECK(notes(d)[0].find("--histogram-every 0.5: histograms every 0.52 (13 sampling intervals "
                         "of 0.04) from t = 0, the last at t = 1.56, not at --until 2") !=
        std::string::npos);
  // a spacing that is whole sampling intervals and reaches --until: no note
  CHECK(notes(run_ok(s, {"--dim", "3", "--n", "500", "--until", "2", "--histogram-every", "0.4"},
                     "g"))
            .empty());
}

TEST_CASE("run --engine edmd --transport too short for two windows: names the --until that "
          "runs",
          "[cli]") {
  Scratch s("edmd-short");
  const std::vector<std::string> args = {"run", "--engine", "edmd", "--dim", "3", "--n", "500",
                                         "--packing", "0.1", "--transport", "--until", "40",
                                         "--out", "o"};
  const Result r = run(args, s.path());
  INFO(r.err);
  CHECK(r.code == 2);
  REQUIRE(lines(r.err).size() == 1);
  CHECK(r.err.rfind("hypergas: --transport: the recording from t = 8 to --until 40 (32 time "
                    "units) is shorter than two correlation windows of --correlation-time 40 "
                    "mean free times",
                    0) == 0);
  CHECK(r.err.find("helfand:") == std::string::npos);  // no recorder's prefix
  CHECK(s.entries() == 0);
  const std::string mark = "run longer: --until ";
  const auto at = r.err.find(mark);
  REQUIRE(at != std::string::npos);
  const std::string until = lines(r.err.substr(at + mark.size()))[0];
  CHECK(std::strtod(until.c_str(), nullptr) > 40.0);
  // the end it names runs
  std::vector<std::string> longer = args;
  longer[11] = until;
  const Result ok = run(longer, s.path());
  INFO(ok.err);
  CHECK(ok.code == 0);
}

TEST_CASE("resume --until suggests ends as short decimals that it accepts", "[cli]") {
  Scratch s("suggest");
  run_ok(s, {"--dim", "3", "--n", "500", "--until", "3", "--every", "0.3", "--checkpoint-every",
             "1"},
         "o");
  const Result r = run(std::vector<std::string>{"resume", "o", "--until", "4"}, s.path());
  CHECK(r.code == 2);
  // 13 and 14 intervals of 0.3: 3.9000000000000004 and 4.2 in binary
  CHECK(r.err == "hypergas: resume --until 4: the run sampled every 0.3 from 0, and a span that "
                 "is not a whole number of those intervals would move its rows; try --until 3.9 "
                 "or 4.2\n");
  const Result ok = run(std::vector<std::string>{"resume", "o", "--until", "4.2"}, s.path());
  INFO(ok.err);
  CHECK(ok.code == 0);
  CHECK(first_column(s.path() / "o" / "moments.csv").size() == 15);
}

#endif
