// CLI tests: --help lists every option of the command-line contract (docs/design.md) with
// its unit or allowed values and its default, and exits 0.
#include <catch2/catch.hpp>

#ifdef HYPERGAS_CLI_PATH
#include "cli/run_cli.hpp"

TEST_CASE("hypergas --help lists the subcommands", "[cli]") {
  cli_test::Scratch s("help");
  const auto r = cli_test::run({"--help"}, s.path());
  CHECK(r.code == 0);
  for (const char* word : {"run", "bench", "report", "--out", "results"})
    CHECK(r.out.find(word) != std::string::npos);
}

TEST_CASE("hypergas --version names the version and the git state", "[cli]") {
  cli_test::Scratch s("version");
  const auto r = cli_test::run({"--version"}, s.path());
  CHECK(r.code == 0);
  INFO(r.out << r.err);
  CHECK(r.out.rfind("hypergas 0.1.0 (git ", 0) == 0);
  CHECK(cli_test::lines(r.out).size() == 1);
  // ... and every summary says the same
  const auto out = s.path() / "out";
  REQUIRE(cli_test::run({"run", "--n", "500", "--until", "1", "--out", out.string()}, s.path())
              .code == 0);
  const std::string summary = cli_test::slurp(out / "summary.json");
  CHECK(summary.find("\"version\": \"0.1.0\"") != std::string::npos);
  CHECK(summary.find("\"git\": \"") != std::string::npos);
}

TEST_CASE("hypergas run --help lists every option with unit and default", "[cli]") {
  cli_test::Scratch s("help");
  const auto r = cli_test::run({"run", "--help"}, s.path());
  REQUIRE(r.code == 0);
  INFO(r.out);
  // Each contract option, followed by the text its line must carry (default or unit).
  const std::vector<std::pair<std::string, std::string>> expected{
      {"--engine", "default dsmc"},   {"--dim", "=3"},
      {"--n", "=10000"},              {"--out", "REQUIRED"},
      {"--json", "last stdout line"}, {"--model", "=hs"},
      {"--init", "default"},          {"--until", "mean collision times; edmd: sigma sqrt(m/kT)] (default 10 for dsmc, 20 for edmd)"},
      {"--every", "default until/50"}, {"--packing", "=0.1"},
      {"--mass-ratio", "=1"},         {"--fraction", "=0.5"},
      {"--seed", "=1"},               {"--threads", "=1"},
      {"--temperature", "=1"}};
  const auto lines = cli_test::lines(r.out);
  for (const auto& [opt, text] : expected) {
    bool found = false;
    for (const auto& l : lines)
      if (l.find(opt + " ") != std::string::npos || l.find(opt + "=") != std::string::npos)
        found = found || l.find(text) != std::string::npos;
    INFO(opt << " should show '" << text << "'");
    CHECK(found);
  }
}
#endif
