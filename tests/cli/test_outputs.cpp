// CLI tests of the outputs' registration (sim/outputs/output.hpp): conservation.csv holds
// its quantities against summary.json's route, an output that another excludes leaves its
// keys to that one, and every file a run writes is declared by one of its outputs (the
// command refuses to commit an undeclared one, so every run of these tests checks it).

#ifdef HYPERGAS_CLI_PATH

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cli/run_cli.hpp"

namespace {
using cli_test::Scratch;
using cli_test::column;
using cli_test::json_number;

/// The largest |x| of a column.
double max_abs(const std::vector<double>& x) {
  double m = 0.0;
  for (double v : x) m = std::max(m, std::fabs(v));
  return m;
}
}  // namespace

TEST_CASE("conservation.csv: energy and momentum at round-off, the summary's route at the end",
          "[cli]") {
  // Two masses (--mass-ratio 2): a sum that dropped the masses would change by O(1) in the
  // first collisions. Round-off grows as a random walk: measured 1.5e-16 (DSMC) and 2e-15
  // (EDMD) at the end of these runs; 1e-12 bounds it with a margin of 500. The last row is
  // against the first sampled state, summary.json's energy_rel_drift against t = 0: the
  // same state for DSMC (the same long double sums: equal to 1e-18, the relative
  // precision of a long double sum of 2000 terms, x 10), and for EDMD the end of the
  // elastic equilibration, whose own change is round-off (measured 4e-16 apart; 1e-14).
  struct Case {
    std::vector<std::string> args;
    double agree;
  };
  const std::vector<Case> cases{
      {{"--dim", "3", "--n", "2000", "--until", "4", "--mass-ratio", "2", "--seed", "5"},
       1e-17},
      {{"--engine", "edmd", "--dim", "3", "--n", "500", "--packing", "0.3", "--until", "4",
        "--mass-ratio", "2", "--seed", "5"},
       1e-14}};
  for (const Case& c : cases) {
    Scratch s("conservation");
    std::vector<std::string> args{"run"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.insert(args.end(), {"--out", (s.path() / "out").string()});
    const auto r = cli_test::run(args, s.path());
    INFO(r.err);
    REQUIRE(r.code == 0);
    const auto csv = s.path() / "out" / "conservation.csv";
    const std::vector<double> t = column(csv, "time"), e = column(csv, "energy_rel_change"),
                              p = column(csv, "momentum_drift");
    REQUIRE(t.size() >= 10);
    CHECK(e.front() == 0.0);
    CHECK(p.front() == 0.0);
    CHECK(max_abs(e) < 1e-12);
    CHECK(max_abs(p) < 1e-12);
    const std::string js = cli_test::slurp(s.path() / "out" / "summary.json");
    CHECK(std::fabs(std::fabs(e.back()) - json_number(js, "energy_rel_drift")) <= c.agree);
    CHECK(std::fabs(p.back() - json_number(js, "momentum_drift")) <= c.agree);
  }
}

TEST_CASE("a run without conserved energy has no conservation.csv", "[cli]") {
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--restitution", "0.8"},
        std::vector<std::string>{"--shear-rate", "0.3"},
        std::vector<std::string>{"--restitution", "0.8", "--drive", "white-noise"}}) {
    Scratch s("no-conservation");
    std::vector<std::string> args{"run", "--dim", "2", "--n", "500", "--until", "2",
                                  "--out", (s.path() / "out").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = cli_test::run(args, s.path());
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK(!cli_test::fs::exists(s.path() / "out" / "conservation.csv"));
  }
}

TEST_CASE("a sheared granular gas has the shear output's keys, not the granular output's",
          "[cli]") {
  // the shear output excludes the granular one (OutputKind::excludes): the steady state's
  // temperature_ratio once, no cooling fits of a gas that does not cool freely
  for (const char* engine : {"dsmc", "edmd"}) {
    Scratch s("shear-granular");
    std::vector<std::string> args{"run", "--engine", engine, "--dim", "2", "--n", "900",
                                  "--until", "4", "--shear-rate", "0.3", "--restitution", "0.9",
                                  "--out", (s.path() / "out").string()};
    if (std::string(engine) == "edmd") args.insert(args.end(), {"--packing", "0.1"});
    const auto r = cli_test::run(args, s.path());
    INFO(engine << ": " << r.err);
    REQUIRE(r.code == 0);
    const std::string js = cli_test::slurp(s.path() / "out" / "summary.json");
    const auto count = [&](const std::string& key) {
      std::size_t n = 0;
      for (auto pos = js.find("\"" + key + "\":"); pos != std::string::npos;
           pos = js.find("\"" + key + "\":", pos + 1))
        ++n;
      return n;
    };
    CHECK(count("temperature_ratio") == 1);
    CHECK(count("a2_mean") == 0);
    CHECK(count("haff_t0") == 0);
    CHECK(count("haff_t0_enskog") == 0);
  }
}

#endif
