// CLI tests: every kind of bad input gets exit code 2, a clear one-line message on stderr
// naming the problem, nothing on stdout, and leaves no file or folder behind.
#include <catch2/catch.hpp>

#ifdef HYPERGAS_CLI_PATH
#include "cli/run_cli.hpp"

using cli_test::Scratch;

namespace {
// Runs the command with `args` plus `--out <scratch>/out`, which must not exist afterwards.
void expect_rejected(std::vector<std::string> args, const std::string& message_part) {
  Scratch s("bad");
  args.push_back("--out");
  args.push_back((s.path() / "out").string());
  const auto r = cli_test::run(args, s.path());
  INFO("args: " << Catch::Detail::stringify(args) << "\nstderr: " << r.err);
  CHECK(r.code == 2);
  CHECK(r.err.find(message_part) != std::string::npos);
  CHECK(r.out.empty());
  CHECK(s.entries() == 0);  // no output folder, no staging folder, no stray file
}
}  // namespace

TEST_CASE("bench and report without hypergas-measure beside the command: exit 2, how to build it",
          "[cli]") {
  // the first build (scripts/setup.sh without arguments) makes only `hypergas`
  Scratch s("solo");
  const auto solo = s.path() / "hypergas";
  cli_test::fs::copy_file(HYPERGAS_CLI_PATH, solo);
  for (const char* tool : {"bench", "report"}) {
    cli_test::Spawn how;
    how.program = solo.string();
    const auto r = cli_test::Child({tool, "--quick"}, s.path(), how).wait();
    INFO(tool << ": " << r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find(std::string("hypergas: ") + tool +
                     " is done by hypergas-measure, which this build did not make") == 0);
    CHECK(r.out.empty());
  }
}

TEST_CASE("run: dimension outside 1..6 is rejected", "[cli]") {
  expect_rejected({"run", "--dim", "0"}, "--dim must be a dimension in 1..6, got 0");
  expect_rejected({"run", "--dim", "7"}, "--dim must be a dimension in 1..6, got 7");
  expect_rejected({"run", "--dim", "-3"}, "got -3");
  expect_rejected({"run", "--dim", "three"}, "--dim");
}

TEST_CASE("run: fewer than two particles is rejected", "[cli]") {
  expect_rejected({"run", "--n", "1"}, "--n must be a number of particles in 2..2^31, got 1");
  expect_rejected({"run", "--n", "0"}, "got 0");
  expect_rejected({"run", "--n", "-5"}, "got -5");
}

TEST_CASE("run: non-finite or negative mass ratio is rejected", "[cli]") {
  for (const char* m : {"-1", "0", "nan", "inf", "-inf"})
    expect_rejected({"run", "--dim", "1", "--mass-ratio", m}, "--mass-ratio must be a finite");
  expect_rejected({"run", "--fraction", "1.5"}, "--fraction must be in [0, 1]");
}

TEST_CASE("an unknown option or subcommand: one line naming the nearest", "[cli]") {
  expect_rejected({"run", "--dim", "3", "--restitutoin", "0.5"},
                  "hypergas: run: unknown option '--restitutoin'; did you mean '--restitution'?");
  expect_rejected({"run", "--packnig", "0.2"}, "did you mean '--packing'?");
  expect_rejected({"run", "--zzzzzz", "1"}, "hypergas: run: unknown option '--zzzzzz'");
  Scratch s("typo");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"runn"}, {"run", "--dim", "3", "--restitutoin", "0.5"}}) {
    const auto r = cli_test::run(args, s.path());
    CHECK(r.code == 2);
    CHECK(cli_test::lines(r.err).size() == 1);  // one line, not the arguments reversed
    if (args[0] == "runn") CHECK(r.err.find("did you mean 'run'?") != std::string::npos);
  }
}

TEST_CASE("run: combinations that mean nothing are rejected", "[cli]") {
  // a second-species share without a second mass was dropped ("fraction": 0 in the summary)
  expect_rejected({"run", "--fraction", "0.3"}, "--fraction is the share of the second mass");
  expect_rejected({"run", "--fraction", "0.3", "--mass-ratio", "1"}, "--mass-ratio other than 1");
  // BKW is an exact solution of Maxwell molecules only
  expect_rejected({"run", "--init", "bkw"}, "--init bkw is the exact solution for Maxwell");
  expect_rejected({"run", "--init", "bkw", "--model", "hs"}, "add --model maxwell (not hs)");
  // 1D elastic, one mass: collisions only swap velocities (KS p 0 at the end, no word)
  expect_rejected({"run", "--dim", "1"}, "--dim 1 with one mass");
  expect_rejected({"run", "--dim", "1", "--init", "maxwell"}, "give --mass-ratio");
}

TEST_CASE("run: non-finite or negative temperature is rejected", "[cli]") {
  for (const char* t : {"-1", "0", "nan", "inf"})
    expect_rejected({"run", "--temperature", t}, "--temperature must be a finite kT > 0");
}

TEST_CASE("run: bad times are rejected", "[cli]") {
  expect_rejected({"run", "--until", "0"}, "--until must be a finite time > 0");
  expect_rejected({"run", "--until", "inf"}, "--until must be a finite time > 0");
  expect_rejected({"run", "--every", "nan"}, "--every must be a finite interval > 0");
}

TEST_CASE("run: packing at or above the D-dimensional jamming density is rejected", "[cli]") {
  // Jamming densities 1, 0.82, 0.64, 0.46, 0.31, 0.20 for D = 1..6 (edmd/box.hpp).
  expect_rejected({"run", "--engine", "edmd", "--dim", "3", "--packing", "0.65"},
                  "jamming density 0.64");
  expect_rejected({"run", "--engine", "edmd", "--dim", "6", "--packing", "0.2"},
                  "jamming density 0.2");
  expect_rejected({"run", "--engine", "edmd", "--dim", "2", "--packing", "0.83"},
                  "jamming density 0.82");
  expect_rejected({"run", "--engine", "edmd", "--dim", "1", "--packing", "1"}, "jamming");
  expect_rejected({"run", "--engine", "edmd", "--packing", "-0.1"}, "--packing must be");
  // the start of a compression lies at or below the target, and is an EDMD option
  expect_rejected({"run", "--engine", "edmd", "--packing", "0.3", "--start-packing", "0.4"},
                  "--start-packing must be > 0 and at most --packing 0.3");
  expect_rejected({"run", "--engine", "edmd", "--start-packing", "nan"}, "--start-packing");
  expect_rejected({"run", "--engine", "dsmc", "--start-packing", "0.2"},
                  "--start-packing applies to --engine edmd only");
}

TEST_CASE("run: unknown names are rejected", "[cli]") {
  expect_rejected({"run", "--engine", "md"}, "unknown engine 'md'");
  expect_rejected({"run", "--model", "soft"}, "unknown model 'soft'");
  expect_rejected({"run", "--init", "nonsense"}, "unknown initial state 'nonsense'");
  expect_rejected({"run", "--engine", "edmd", "--model", "maxwell"}, "--engine dsmc only");
  expect_rejected({"run", "--no-such-option", "1"}, "--no-such-option");
  expect_rejected({"run", "--threads", "0"}, "--threads must be in 1..256, got 0");
  expect_rejected({"run", "--engine", "edmd", "--threads", "2"}, "--engine dsmc only");
}

TEST_CASE("run: numbers are parsed whole and range-checked; repeats and strays refused",
          "[cli]") {
  expect_rejected({"run", "--until=-1"}, "--until must be a finite time > 0 and at most 1e12, got -1");
  expect_rejected({"run", "--until", "-1"},
                  "--until must be a finite time > 0 and at most 1e12, got -1");
  expect_rejected({"run", "--every=-1"}, "--every must be a finite interval > 0, got -1");
  expect_rejected({"run", "--every", "0"}, "--every must be a finite interval > 0");
  expect_rejected({"run", "--until", "nan"}, "--until must be a finite time > 0 and at most 1e12, got nan");
  expect_rejected({"run", "--until", "1e400"}, "--until must be a number within double range");
  expect_rejected({"run", "--until", "1e300"}, "--until must be a finite time > 0 and at most 1e12, got 1e+300");
  expect_rejected({"run", "--until", "1", "--every", "1e-9"}, "samples; at most 1e6");
  expect_rejected({"run", "--n", "10x"}, "--n must be an integer, got '10x'");
  expect_rejected({"run", "--n", "0x10"}, "--n must be an integer, got '0x10'");
  expect_rejected({"run", "--n", ""}, "--n must be an integer, got ''");
  expect_rejected({"run", "--n", "2.5"}, "--n must be an integer, got '2.5'");
  expect_rejected({"run", "--n", "99999999999"}, "--n must be a number of particles in 2..2^31, got 99999999999");
  // 2e9 particles of 6D EDMD need over 500 GB: more than any machine this runs on.
  expect_rejected({"run", "--engine", "edmd", "--dim", "6", "--n", "2000000000"},
                  "GB of memory");
  expect_rejected({"run", "--seed", "-1"}, "--seed must be an integer >= 0");
  expect_rejected({"run", "--seed", "1e3"}, "--seed must be an integer >= 0");
  expect_rejected({"run", "--packing", "0.1.2"}, "--packing must be a number, got '0.1.2'");
  expect_rejected({"run", "--n", "10", "--n", "20"}, "--n was given more than once");
  expect_rejected({"run", "--bogus", "1"}, "--bogus");
  expect_rejected({"run", "--engine", "dsmc", "--packing", "0.2"},
                  "--packing applies to --engine edmd only");
  expect_rejected({"run", "--engine", "edmd", "--temperature", "1"}, "--engine dsmc only");
  expect_rejected({"run", "--engine", "edmd", "--threads", "1"}, "--engine dsmc only");
  expect_rejected({"run", "--vhs-exponent", "0.3"}, "--vhs-exponent applies to --model vhs");
  expect_rejected({"run", "--checkpoint-every", "0"}, "--checkpoint-every must be a finite");
  expect_rejected({"run", "--checkpoint-wall", "5x"}, "unknown unit 'x'");
  expect_rejected({"run", "--checkpoint-wall", "-1min"}, "--checkpoint-wall must be");
  expect_rejected({"run", "--replicas", "2", "--checkpoint-every", "1"}, "need --replicas 1");
  expect_rejected({"run", "--replicas", "0"}, "--replicas must be in 1..64");
  expect_rejected({"run", "--engine", "edmd", "--replicas", "2"}, "--engine dsmc only");
}

TEST_CASE("run: --n 1e4 is read as 10000", "[cli]") {
  Scratch s("sci");
  const auto r = cli_test::run(
      {"run", "--n", "1e4", "--until", "0.1", "--out", (s.path() / "o").string(), "--json"},
      s.path());
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("\"n\": 10000,") != std::string::npos);
}

TEST_CASE("run: an unwritable output folder is rejected and nothing is created", "[cli]") {
  // A path below a regular file cannot be created, even by root (ENOTDIR).
  Scratch s("unwritable");
  std::ofstream(s.path() / "plain-file") << "x";
  const auto target = s.path() / "plain-file" / "sub" / "out";
  const auto r = cli_test::run({"run", "--n", "100", "--until", "0.1", "--out", target.string()},
                               s.path());
  INFO("stderr: " << r.err);
  CHECK(r.code == 2);
  CHECK(r.err.find("is not writable") != std::string::npos);
  CHECK(s.entries() == 1);  // only the plain file

  // A missing parent chain is created and removed again when the folder turns out unusable:
  // here the output "folder" is an existing regular file.
  const auto r2 = cli_test::run(
      {"run", "--n", "100", "--until", "0.1", "--out", (s.path() / "plain-file").string()},
      s.path());
  CHECK(r2.code == 2);
  CHECK(r2.err.find("not a folder") != std::string::npos);
  CHECK(s.entries() == 1);
}

TEST_CASE("bench and the default scene reject bad input too", "[cli]") {
  Scratch s("bench");
  auto r = cli_test::run({"bench", "--dim", "9"}, s.path());
  CHECK(r.code == 2);
  CHECK(r.err.find("--dim must be a dimension in 1..6, got 9") != std::string::npos);
  r = cli_test::run({"bench", "--engine", "nope"}, s.path());
  CHECK(r.code == 2);
  CHECK(r.err.find("unknown engine 'nope'") != std::string::npos);
  r = cli_test::run({"--n", "1", "--out", (s.path() / "res").string()}, s.path());
  CHECK(r.code == 2);
  CHECK(r.err.find("--n must be at least") != std::string::npos);
  r = cli_test::run({"--until", "-1", "--out", (s.path() / "res").string()}, s.path());
  CHECK(r.code == 2);
  CHECK(s.entries() == 0);
}

TEST_CASE("run --transport: what it cannot measure is rejected", "[cli]") {
  const std::vector<std::string> ok{"run", "--transport", "--until", "500"};
  const auto with = [&](std::vector<std::string> extra) {
    auto a = ok;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  expect_rejected(with({"--dim", "1"}), "--transport needs --dim >= 2");
  expect_rejected(with({"--mass-ratio", "2"}), "one-species gas");
  expect_rejected(with({"--n", "50"}), "--transport needs --n >= 100");
  expect_rejected(with({"--replicas", "2"}), "--transport needs --replicas 1");
  expect_rejected(with({"--checkpoint-every", "10"}), "cannot be checkpointed");
  expect_rejected({"run", "--transport", "--until", "100"},
                  "needs --until >= 20 + 10 --correlation-time = 420");
  expect_rejected(with({"--correlation-time", "0.1"}), "at least 4 --correlation-dt");
  expect_rejected(with({"--correlation-dt", "0"}), "--correlation-dt must be");
  expect_rejected(with({"--tagged", "0"}), "--tagged must be in 1..4096");
  expect_rejected({"run", "--tagged", "8"}, "--tagged applies with --transport only");
}

TEST_CASE("run --engine edmd --transport and --structure: bad combinations are rejected",
          "[cli]") {
  const std::vector<std::string> ok{"run", "--engine", "edmd", "--until", "100"};
  const auto with = [&](std::vector<std::string> extra) {
    auto a = ok;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  expect_rejected(with({"--transport", "--mass-ratio", "2"}), "one-species gas");
  expect_rejected(with({"--transport", "--checkpoint-every", "10"}), "cannot be checkpointed");
  expect_rejected(with({"--structure", "--checkpoint-wall", "1h"}), "cannot be checkpointed");
  expect_rejected(with({"--rdf-max", "3"}), "--rdf-max applies with --structure only");
  expect_rejected(with({"--k-max", "3"}), "--k-max applies with --structure only");
  expect_rejected(with({"--structure", "--rdf-max", "1"}), "--rdf-max must be");
  expect_rejected(with({"--structure", "--k-max", "nan"}), "--k-max");
  expect_rejected({"run", "--structure"}, "--structure applies to --engine edmd only");
  // the recording's length in mean free times is known once the run has measured them:
  // a run too short for two correlation windows stops with a message and writes nothing
  expect_rejected({"run", "--engine", "edmd", "--transport", "--until", "5"},
                  "shorter than two correlation windows");
}

TEST_CASE("run: granular options out of range or in the wrong combination are rejected",
          "[cli]") {
  for (const char* a : {"-0.1", "1.5", "nan", "inf"})
    expect_rejected({"run", "--restitution", a},
                    std::string("--restitution must be in [0, 1], got ") + a);
  expect_rejected({"run", "--restitution", "abc"}, "--restitution must be a number, got 'abc'");
  expect_rejected({"run", "--engine", "edmd", "--restitution", "2"}, "--restitution must be in");
  // the white-noise drive heats an elastic gas without bound, and is a DSMC option
  expect_rejected({"run", "--drive", "white-noise"}, "--drive white-noise needs --restitution < 1");
  expect_rejected({"run", "--drive", "white-noise", "--restitution", "1"},
                  "--drive white-noise needs --restitution < 1");
  expect_rejected({"run", "--drive", "white-noise", "--restitution", "0.5", "--model", "maxwell"},
                  "--drive white-noise is defined for --model hs only");
  expect_rejected({"run", "--drive", "bogus"}, "--drive: unknown drive 'bogus'");
  expect_rejected({"run", "--restitution", "0.5", "--drive-dt", "0.1"},
                  "--drive-dt applies with --drive white-noise only");
  expect_rejected({"run", "--drive-dt", "0.1"}, "--drive-dt applies with --drive white-noise only");
  // the shear flow (dsmc/shear.hpp): D >= 2, a finite rate in [0, 100], the exact scheme,
  // a thermostat only with shear and only for an elastic gas, not with --transport
  expect_rejected({"run", "--shear-rate", "1", "--dim", "1", "--mass-ratio", "3"},
                  "--shear-rate needs --dim >= 2");
  for (const char* a : {"-1", "nan", "inf", "101", "x"})
    expect_rejected({"run", "--shear-rate", a}, "--shear-rate");
  expect_rejected({"run", "--thermostat", "isokinetic"},
                  "--thermostat isokinetic needs --shear-rate > 0");
  expect_rejected({"run", "--shear-rate", "1", "--thermostat", "nose"},
                  "--thermostat: unknown thermostat 'nose'");
  expect_rejected({"run", "--shear-rate", "1", "--scheme", "lanes"},
                  "--shear-rate runs on --scheme exact only");
  expect_rejected({"run", "--shear-rate", "1", "--scheme", "ntc"},
                  "--shear-rate runs on --scheme exact only");
  expect_rejected({"run", "--shear-rate", "1", "--thermostat", "isokinetic", "--restitution",
                   "0.9"},
                  "--thermostat isokinetic holds an elastic gas");
  expect_rejected({"run", "--shear-rate", "1", "--restitution", "0.5", "--drive", "white-noise"},
                  "--shear-rate and --drive white-noise cannot be combined");
  expect_rejected({"run", "--shear-rate", "1", "--transport", "--until", "500"},
                  "--transport measures the gas at equilibrium");
  // EDMD: Lees-Edwards needs 4 cells per side; --structure is an equilibrium measurement
  expect_rejected({"run", "--engine", "edmd", "--shear-rate", "1", "--n", "30", "--packing",
                   "0.3"},
                  "at least 4 cells per side");
  expect_rejected({"run", "--engine", "edmd", "--shear-rate", "1", "--structure"},
                  "--structure measures the fluid at equilibrium");
  expect_rejected({"run", "--engine", "edmd", "--shear-rate", "1", "--dim", "1"},
                  "--shear-rate needs --dim >= 2");
  // a periodic H5MD box has no Lees-Edwards offset: a sheared EDMD trajectory is refused
  expect_rejected({"run", "--engine", "edmd", "--shear-rate", "1", "--trajectory-every", "1"},
                  "--trajectory-every cannot be combined with --shear-rate in EDMD");
  expect_rejected({"run", "--restitution", "0.5", "--drive", "white-noise", "--drive-dt", "0"},
                  "--drive-dt must be a finite interval > 0 and at most 1");
  expect_rejected({"run", "--engine", "edmd", "--drive", "white-noise", "--restitution", "0.5"},
                  "--drive applies to --engine dsmc only");
  expect_rejected({"run", "--engine", "edmd", "--restitution", "0.5", "--drive-dt", "0.1"},
                  "--drive-dt applies to --engine dsmc only");
  // the TC model acts on inelastic EDMD collisions only
  expect_rejected({"run", "--engine", "edmd", "--tc-time", "0.1"},
                  "--tc-time applies with --restitution < 1 only");
  expect_rejected({"run", "--engine", "edmd", "--tc-time", "0.1", "--restitution", "1"},
                  "--tc-time applies with --restitution < 1 only");
  expect_rejected({"run", "--engine", "edmd", "--restitution", "0.5", "--tc-time", "-1"},
                  "--tc-time must be a finite time >= 0");
  expect_rejected({"run", "--restitution", "0.5", "--tc-time", "0.1"},
                  "--tc-time applies to --engine edmd only");
  // transport and structure measure the elastic fluid at equilibrium
  expect_rejected({"run", "--transport", "--until", "500", "--restitution", "0.9"},
                  "--transport measures the elastic gas at equilibrium: leave out --restitution");
  expect_rejected(
      {"run", "--engine", "edmd", "--transport", "--until", "100", "--restitution", "0.9"},
      "--transport measures the elastic gas at equilibrium");
  expect_rejected(
      {"run", "--engine", "edmd", "--structure", "--until", "100", "--restitution", "0.9"},
      "--structure measures the elastic fluid at equilibrium: leave out --restitution");
}
#endif

TEST_CASE("run: a scheme's options without that scheme, or out of range, are rejected", "[cli]") {
  expect_rejected({"run", "--scheme", "euler"}, "unknown DSMC scheme 'euler'");
  expect_rejected({"run", "--dt", "0.1"}, "--dt applies with --scheme ntc only");
  expect_rejected({"run", "--scheme", "ntc", "--dt", "0"}, "--dt must be a finite step > 0");
  expect_rejected({"run", "--lane-size", "64"}, "--lane-size applies with --scheme lanes only");
  expect_rejected({"run", "--scheme", "ntc", "--epoch", "2"},
                  "--epoch applies with --scheme lanes only");
  expect_rejected({"run", "--scheme", "lanes", "--lane-size", "1"},
                  "--lane-size must be 0 (the default) or at least 2");
  expect_rejected({"run", "--scheme", "lanes", "--epoch", "0"}, "--epoch must be a finite time > 0");
  expect_rejected({"run", "--scheme", "ntc", "--transport", "--until", "420"},
                  "--transport needs --scheme exact or lanes");
  expect_rejected({"run", "--scheme", "lanes", "--transport", "--tagged", "8", "--until", "420"},
                  "--tagged needs --scheme exact");
  expect_rejected({"run", "--engine", "edmd", "--scheme", "lanes"},
                  "--scheme applies to --engine dsmc only");
}
