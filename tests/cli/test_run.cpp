// CLI tests: happy paths of `hypergas run` and of the default scene. The files of the
// contract (docs/design.md) exist with their columns, summary.json has its keys, --json
// prints the same object as the last stdout line, and an interrupted run leaves only its
// checkpoint.
#include <catch2/catch.hpp>

#ifdef HYPERGAS_CLI_PATH
#include "cli/run_cli.hpp"

namespace {
using cli_test::Scratch;

// The header line of a CSV file.
std::string header(const cli_test::fs::path& p) {
  const auto l = cli_test::lines(cli_test::slurp(p));
  return l.empty() ? std::string() : l.front();
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

void check_summary_keys(const std::string& json, const std::vector<std::string>& keys) {
  for (const auto& k : keys) {
    INFO("key " << k << " in " << json);
    CHECK(json.find("\"" + k + "\":") != std::string::npos);
  }
}

const std::vector<std::string> common_keys{
    "dim", "engine", "model", "n", "seed", "collisions", "wall_s", "collisions_per_s",
    "energy_rel_drift", "momentum_drift"};
}  // namespace

TEST_CASE("run --engine dsmc writes the contract's files", "[cli]") {
  Scratch s("run");
  const auto out = s.path() / "nested" / "out";
  const auto r = cli_test::run({"run", "--engine", "dsmc", "--dim", "3", "--n", "2000",
                                "--until", "2", "--every", "0.5", "--seed", "7", "--out",
                                out.string(), "--json"},
                               s.path());
  INFO("stderr: " << r.err << "\nstdout: " << r.out);
  REQUIRE(r.code == 0);
  CHECK(starts_with(header(out / "moments.csv"),
                    "time,collisions_per_particle,m2,m4,kurtosis_x"));
  CHECK(starts_with(header(out / "speed_histogram.csv"), "lo,hi,count,density,maxwell_density"));
  // Rows at t = 0, 0.5, ..., 2: a header and five lines.
  CHECK(cli_test::lines(cli_test::slurp(out / "moments.csv")).size() == 6);
  const std::string summary = cli_test::slurp(out / "summary.json");
  check_summary_keys(summary, common_keys);
  CHECK(summary.find("\"engine\": \"dsmc\"") != std::string::npos);
  CHECK(summary.find("\"dim\": 3") != std::string::npos);
  // --json: the summary object is the last line of stdout.
  const auto lines = cli_test::lines(r.out);
  REQUIRE(!lines.empty());
  CHECK(lines.back() + "\n" == summary);
  // No staging folder is left in the output folder.
  for (const auto& e : cli_test::fs::directory_iterator(out))
    CHECK(e.path().filename().string().rfind(".hypergas-staging", 0) != 0);
}

TEST_CASE("run in 1D with two masses, and with Maxwell molecules in 5D", "[cli]") {
  Scratch s("run");
  auto r = cli_test::run({"run", "--dim", "1", "--n", "1000", "--mass-ratio", "3", "--until",
                          "1", "--out", (s.path() / "a").string()},
                         s.path());
  CHECK(r.code == 0);
  CHECK(cli_test::fs::exists(s.path() / "a" / "summary.json"));
  r = cli_test::run({"run", "--dim", "5", "--n", "1000", "--model", "maxwell", "--init", "bkw",
                     "--until", "1", "--out", (s.path() / "b").string(), "--json"},
                    s.path());
  CHECK(r.code == 0);
  CHECK(r.out.find("\"model\": \"maxwell\"") != std::string::npos);
}

TEST_CASE("an interrupted run leaves its checkpoint and nothing else", "[cli]") {
  Scratch s("interrupt");
  const auto out = s.path() / "out";
  // Ctrl-C as soon as the run holds its output folder (readiness: its staging folder, made
  // right after it takes the folder's lock, with the interrupt handler installed before).
  // The run is 2000 time units long, so it is far from its end; it stops at its next
  // sampling time.
  cli_test::Child c({"run", "--dim", "3", "--n", "200000", "--until", "2000", "--every", "1",
                     "--out", out.string()},
                    s.path());
  const bool started = c.wait_until([&] { return cli_test::has_staging(out); });
  c.signal(SIGINT);
  const auto r = c.wait();
  INFO("stderr: " << r.err);
  REQUIRE(started);
  CHECK(r.signal == 0);
  CHECK(r.code == 130);
  CHECK(r.err.find("interrupted") != std::string::npos);
  CHECK(r.err.find("hypergas resume " + out.string()) != std::string::npos);
  // Only the checkpoint (tests/cli/test_checkpoint.cpp resumes such runs): no CSV, no
  // staging folder, no temporary file. The scratch folder also holds the captured output.
  CHECK(cli_test::fs::exists(out / "checkpoint.hgck"));
  std::size_t in_out = 0;
  for ([[maybe_unused]] const auto& e : cli_test::fs::recursive_directory_iterator(out)) ++in_out;
  CHECK(in_out == 1);  // out/checkpoint.hgck
}

TEST_CASE("the default scene prints one row per D and writes CSV under --out", "[cli]") {
  Scratch s("scene");
  const auto out = s.path() / "results";
  const auto r = cli_test::run({"--out", out.string(), "--n", "4000", "--until", "4"}, s.path());
  INFO("stderr: " << r.err);
  REQUIRE(r.code == 0);
  const auto lines = cli_test::lines(r.out);
  for (int d = 1; d <= 6; ++d) {
    const std::string prefix = {' ', static_cast<char>('0' + d), ' ', ' '};
    bool row = false;
    for (const auto& l : lines) row = row || starts_with(l, prefix);
    INFO("row for D = " << d);
    CHECK(row);
    CHECK(starts_with(header(out / ("relaxation_D" + std::to_string(d) + ".csv")),
                      "time,collisions_per_particle,m2,m4,kurtosis_x"));
    CHECK(cli_test::fs::exists(out / ("speed_histogram_D" + std::to_string(d) + ".csv")));
  }
  CHECK(starts_with(header(out / "summary.csv"), "dim,n,mass_ratio"));
}
#endif

#ifdef HYPERGAS_CLI_PATH
TEST_CASE("bench prints one JSON object per line on stdout", "[cli]") {
  cli_test::Scratch s("bench");
  const auto r = cli_test::run({"bench", "--engine", "all", "--dim", "2", "--n", "1000",
                                "--reps", "1", "--min-collisions", "2000"},
                               s.path());
  INFO("stderr: " << r.err << "\nstdout: " << r.out);
  REQUIRE(r.code == 0);
  const auto lines = cli_test::lines(r.out);
  REQUIRE(lines.size() >= 2);  // at least one DSMC and one EDMD line
  bool dsmc = false, edmd = false;
  for (const auto& l : lines) {
    CHECK(l.front() == '{');
    CHECK(l.back() == '}');
    CHECK(l.find("\"collisions_per_s\"") != std::string::npos);
    dsmc = dsmc || l.find("\"bench\":\"dsmc\"") != std::string::npos;
    edmd = edmd || l.find("\"bench\":\"edmd\"") != std::string::npos;
  }
  CHECK(dsmc);
  CHECK(edmd);
}

TEST_CASE("run --replicas 2 runs two DSMC replicas; replica 0 equals the one-replica run",
          "[cli]") {
  cli_test::Scratch s("replicas");
  const std::vector<std::string> base{"run", "--dim", "3", "--n", "2000", "--until", "1",
                                      "--seed", "11"};
  auto one = base, two = base;
  one.insert(one.end(), {"--out", (s.path() / "one").string()});
  two.insert(two.end(), {"--out", (s.path() / "two").string(), "--replicas", "2"});
  REQUIRE(cli_test::run(one, s.path()).code == 0);
  REQUIRE(cli_test::run(two, s.path()).code == 0);
  // Same seed for replica 0: bit-identical moments.
  CHECK(cli_test::slurp(s.path() / "one" / "moments.csv") ==
        cli_test::slurp(s.path() / "two" / "moments.csv"));
  CHECK(cli_test::slurp(s.path() / "two" / "summary.json").find("\"replicas\": 2") !=
        std::string::npos);
}

TEST_CASE("run --threads T writes the same files for T = 1, 2, 3", "[cli]") {
  // 64000 particles: the smallest 3D system the engine splits over threads.
  cli_test::Scratch s("threads");
  const std::vector<std::string> base{"run", "--dim", "3", "--n", "64000", "--until", "2",
                                      "--init", "beams", "--seed", "5"};
  for (const char* t : {"1", "2", "3"}) {
    auto args = base;
    args.insert(args.end(), {"--out", (s.path() / t).string(), "--threads", t});
    REQUIRE(cli_test::run(args, s.path()).code == 0);
  }
  for (const char* f : {"moments.csv", "speed_histogram.csv"})
    for (const char* t : {"2", "3"}) {
      INFO(f << " with --threads " << t);
      CHECK(cli_test::slurp(s.path() / "1" / f) == cli_test::slurp(s.path() / t / f));
    }
}

TEST_CASE("run --transport writes transport.csv, correlations.csv and transport.png", "[cli]") {
  Scratch s("transport");
  const auto out = s.path() / "out";
  const auto r = cli_test::run({"run", "--engine", "dsmc", "--dim", "2", "--model", "maxwell",
                                "--n", "200", "--until", "420", "--transport", "--seed", "3",
                                "--out", out.string(), "--json"},
                               s.path());
  INFO("stderr: " << r.err << "\nstdout: " << r.out);
  REQUIRE(r.code == 0);
  CHECK(header(out / "transport.csv") ==
        "coefficient,value,error,first_sonine,ratio,ratio_error,t_cut,tail,c0,decay_rate,"
        "decay_rate_error,first_sonine_rate,enskog,enskog_ratio,enskog_ratio_error");
  const auto rows = cli_test::lines(cli_test::slurp(out / "transport.csv"));
  REQUIRE(rows.size() == 5);
  CHECK(starts_with(rows[1], "viscosity,"));
  CHECK(starts_with(rows[2], "thermal_conductivity,"));
  CHECK(starts_with(rows[3], "self_diffusion,"));
  CHECK(starts_with(rows[4], "self_diffusion_einstein,"));
  CHECK(starts_with(header(out / "correlations.csv"), "time,viscosity,viscosity_sonine,"));
  // lags 0 .. 40 in steps of the sampling interval (0.05, rounded to a multiple of 16 lags)
  CHECK(cli_test::lines(cli_test::slurp(out / "correlations.csv")).size() == 1 + 816);
  CHECK(cli_test::fs::exists(out / "transport.png"));
  check_summary_keys(cli_test::slurp(out / "summary.json"),
                     {"viscosity", "viscosity_error", "viscosity_ratio", "thermal_conductivity",
                      "self_diffusion_ratio_error", "transport_samples"});
}

TEST_CASE("run --engine edmd --transport --structure writes its files", "[cli]") {
  Scratch s("edmd_transport");
  const auto out = s.path() / "out";
  const auto r = cli_test::run({"run", "--engine", "edmd", "--dim", "3", "--packing", "0.3",
                                "--n", "300", "--until", "60", "--transport", "--structure",
                                "--correlation-time", "10", "--rdf-max", "3", "--k-max", "5",
                                "--seed", "3", "--out", out.string(), "--json"},
                               s.path());
  INFO("stderr: " << r.err << "\nstdout: " << r.out);
  REQUIRE(r.code == 0);
  CHECK(header(out / "transport.csv") ==
        "coefficient,value,error,first_sonine,ratio,ratio_error,t_cut,tail,c0,decay_rate,"
        "decay_rate_error,first_sonine_rate,enskog,enskog_ratio,enskog_ratio_error");
  const auto rows = cli_test::lines(cli_test::slurp(out / "transport.csv"));
  REQUIRE(rows.size() == 1 + 12 + 3);
  CHECK(starts_with(rows[1], "viscosity,"));
  CHECK(starts_with(rows[7], "thermal_conductivity,"));
  CHECK(starts_with(rows[15], "self_diffusion_yeh_hummer,"));
  CHECK(header(out / "correlations.csv") ==
        "time,viscosity,thermal_conductivity,self_diffusion,viscosity_helfand,"
        "thermal_conductivity_helfand");
  CHECK(header(out / "rdf.csv") == "r,g,error");
  CHECK(header(out / "structure_factor.csv") == "k,S,error,vectors");
  // bins of 0.02 up to --rdf-max 3
  CHECK(cli_test::lines(cli_test::slurp(out / "rdf.csv")).size() == 1 + 150);
  for (const char* f : {"transport.png", "structure.png"}) CHECK(cli_test::fs::exists(out / f));
  check_summary_keys(cli_test::slurp(out / "summary.json"),
                     {"viscosity", "viscosity_error", "thermal_conductivity_green_kubo",
                      "self_diffusion_einstein", "transport_chi", "contact_value_rdf",
                      "contact_value_rdf_error", "contact_value_from_Z"});
}
#endif
