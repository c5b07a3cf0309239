// CLI tests: an output folder holds one run. A run into the folder of an earlier run
// replaces that run's files (none of the earlier run's files stays behind), and a folder
// holding a file that hypergas did not write there is refused before anything changes.
#include <catch2/catch.hpp>

#ifdef HYPERGAS_CLI_PATH
#include <algorithm>
#include <set>
#include <string>

#include "cli/run_cli.hpp"

namespace {
using cli_test::fs::path;
using cli_test::Scratch;

/// The names of the visible files in `dir`.
std::set<std::string> files(const path& dir) {
  std::set<std::string> names;
  for (const auto& e : cli_test::fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (n[0] != '.') names.insert(n);
  }
  return names;
}
}  // namespace

TEST_CASE("a run into an earlier run's folder leaves none of its files", "[cli]") {
  Scratch s("reuse");
  const path out = s.path() / "out";
  const auto edmd = cli_test::run({"run", "--engine", "edmd", "--dim", "3", "--n", "256",
                                   "--packing", "0.2", "--until", "4", "--structure", "--out",
                                   out.string()},
                                  s.path());
  INFO("stderr: " << edmd.err);
  REQUIRE(edmd.code == 0);
  REQUIRE(files(out).count("rdf.csv") == 1);
  const auto dsmc = cli_test::run({"run", "--engine", "dsmc", "--dim", "3", "--n", "1000",
                                   "--until", "1", "--out", out.string()},
                                  s.path());
  INFO("stderr: " << dsmc.err);
  REQUIRE(dsmc.code == 0);
  // exactly the files of a DSMC run into a new folder
  const path fresh = s.path() / "fresh";
  REQUIRE(cli_test::run({"run", "--engine", "dsmc", "--dim", "3", "--n", "1000", "--until", "1",
                         "--out", fresh.string()},
                        s.path())
              .code == 0);
  CHECK(files(out) == files(fresh));
  for (const char* stale : {"rdf.csv", "structure_factor.csv", "vacf.csv", "structure.png"})
    CHECK(files(out).count(stale) == 0);
}

TEST_CASE("a folder with a file hypergas did not write is refused, unchanged", "[cli]") {
  Scratch s("foreign");
  const path out = s.path() / "out";
  cli_test::fs::create_directories(out);
  {
    std::ofstream notes(out / "notes.txt");
    notes << "mine\n";
  }
  const auto before = cli_test::stamp(out / "notes.txt");
  const auto r = cli_test::run({"run", "--engine", "dsmc", "--dim", "3", "--n", "1000",
                                "--until", "1", "--out", out.string()},
                               s.path());
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  const auto err = cli_test::lines(r.err);
  REQUIRE(err.size() == 1);
  CHECK(err[0].find("notes.txt") != std::string::npos);
  CHECK(files(out) == std::set<std::string>{"notes.txt"});
  CHECK(cli_test::stamp(out / "notes.txt") == before);
  // also after a run: the file arrived later, so a second run into the folder is refused
  const path used = s.path() / "used";
  REQUIRE(cli_test::run({"run", "--engine", "dsmc", "--dim", "2", "--n", "500", "--until", "1",
                         "--out", used.string()},
                        s.path())
              .code == 0);
  { std::ofstream(used / "plot.py") << "# mine\n"; }
  const auto files_before = files(used);
  const auto again = cli_test::run({"run", "--engine", "dsmc", "--dim", "2", "--n", "500",
                                    "--until", "1", "--out", used.string()},
                                   s.path());
  CHECK(again.code == 2);
  CHECK(files(used) == files_before);
}
#endif
