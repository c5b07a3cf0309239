// Atomic CSV / JSON output (analysis/output.hpp) and the files of MomentsRecorder
// (docs/design.md: the file contract). Deterministic.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/error.hpp"
#include "test_analysis_support.hpp"

using namespace hypergas;
using namespace hypergas::analysis;
namespace fs = std::filesystem;

TEST_CASE("CSV is written atomically with its header and leaves no temporary file", "[analysis]") {
  test::TempDir dir;
  const fs::path f = dir.path / "a.csv";
  write_csv(f.string(), {"lag", "vacf"}, {{0, 1.5}, {1, 0.1}, {2, NAN}});
  CHECK(test::read_text(f) == "lag,vacf\n0,1.5\n1,0.10000000000000001\n2,\n");  // NaN: empty field
  CHECK(dir.entries() == 1);
  // Overwriting replaces the file as a whole.
  write_csv(f.string(), {"x"}, {{3}});
  CHECK(test::read_text(f) == "x\n3\n");
  CHECK(dir.entries() == 1);
}

TEST_CASE("A failing write leaves the old file and no partial file", "[analysis]") {
  test::TempDir dir;
  const fs::path f = dir.path / "keep.csv";
  write_csv(f.string(), {"x"}, {{1}});
  // The writer fails half way: the old content survives, nothing else is left.
  CHECK_THROWS_AS(write_file_atomic(f.string(),
                                    [](std::ostream& os) {
                                      os << "half a file";
                                      throw std::runtime_error("disk on fire");
                                    }),
                  std::runtime_error);
  CHECK(test::read_text(f) == "x\n1\n");
  CHECK(dir.entries() == 1);
  // A row of the wrong length is refused before anything is written.
  CHECK_THROWS_AS(write_csv((dir.path / "bad.csv").string(), {"a", "b"}, {{1}}), InvalidInput);
  CHECK(dir.entries() == 1);
}

TEST_CASE("A missing or unwritable folder is an InvalidInput naming the path", "[analysis]") {
  test::TempDir dir;
  const std::string missing = (dir.path / "no" / "such" / "x.csv").string();
  CHECK_THROWS_WITH(write_csv(missing, {"x"}, {{1}}),
                    Catch::Contains(missing) && Catch::Contains("does not exist"));
  CHECK_THROWS_AS(write_csv(missing, {"x"}, {{1}}), InvalidInput);
  // /proc is a folder nobody, root included, can create files in.
  CHECK_THROWS_WITH(write_csv("/proc/hypergas_x.csv", {"x"}, {{1}}),
                    Catch::Contains("/proc/hypergas_x.csv") && Catch::Contains("cannot create"));
  // A destination that is a folder: the rename fails and the temporary is removed.
  fs::create_directory(dir.path / "sub");
  CHECK_THROWS_AS(write_csv((dir.path / "sub").string(), {"x"}, {{1}}), InvalidInput);
  CHECK(dir.entries() == 1);
  fs::remove(dir.path / "sub");
  if (::geteuid() != 0) {  // a read-only folder: root may write anyway, so only as a user
    fs::permissions(dir.path, fs::perms::owner_read | fs::perms::owner_exec);
    const std::string ro = (dir.path / "x.csv").string();
    CHECK_THROWS_AS(write_json(ro, {{"a", 1.0}}), InvalidInput);
    CHECK_THROWS_WITH(write_json(ro, {{"a", 1.0}}), Catch::Contains(ro));
    fs::permissions(dir.path, fs::perms::owner_all);
    CHECK(dir.entries() == 0);
  }
}

TEST_CASE("JSON summary: one object, keys in order, NaN as null", "[analysis]") {
  const JsonObject o = {{"dim", std::int64_t{3}},
                        {"engine", std::string("dsmc \"x\"")},
                        {"wall_s", 0.25},
                        {"drift", NAN},
                        {"ok", true}};
  CHECK(to_json(o) ==
        R"({"dim": 3, "engine": "dsmc \"x\"", "wall_s": 0.25, "drift": null, "ok": true})");
  test::TempDir dir;
  write_json((dir.path / "summary.json").string(), o);
  CHECK(test::read_text(dir.path / "summary.json") == to_json(o) + "\n");
}

TEST_CASE("MomentsRecorder writes moments.csv and speed_histogram.csv per docs/design.md",
          "[analysis]") {
  test::OwnedState st(3, 20000);
  Rng rng(51);
  MomentsRecorder rec(40);
  CHECK_THROWS_AS(rec.write_moments_csv("/tmp/never.csv"), InvalidInput);
  for (int k = 0; k < 3; ++k) {
    test::fill_maxwell(st, rng, 2.0);
    Snapshot s = st.snapshot();
    s.time = 0.5 * k;
    s.collisions_per_particle = 1.0 * k;
    rec.observe(s);
  }
  test::TempDir dir;
  rec.write_moments_csv((dir.path / "moments.csv").string());
  rec.write_speed_histogram_csv((dir.path / "speed_histogram.csv").string());
  const std::string m = test::read_text(dir.path / "moments.csv");
  CHECK(m.rfind("time,collisions_per_particle,m2,m4,kurtosis_x,", 0) == 0);
  CHECK(std::count(m.begin(), m.end(), '\n') == 4);
  const std::string h = test::read_text(dir.path / "speed_histogram.csv");
  CHECK(h.rfind("lo,hi,count,density,maxwell_density,sonine_density\n", 0) == 0);
  CHECK(std::count(h.begin(), h.end(), '\n') == 41);
  // Columns are consistent: counts sum to n less the (rare) overflow, both densities
  // integrate to ~1 (the range covers MB up to tail 1e-7), density = count / (n width).
  {
    std::istringstream in(h);
    std::string line;
    std::getline(in, line);
    double counts = 0, hist_mass = 0, mb_mass = 0, sonine_mass = 0;
    while (std::getline(in, line)) {
      double lo, hi, c, dens, mb, son;
      REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &lo, &hi, &c, &dens, &mb,
                          &son) == 6);
      CHECK(dens == Approx(c / (20000.0 * (hi - lo))).epsilon(1e-12));
      counts += c;
      hist_mass += dens * (hi - lo);
      mb_mass += mb * (hi - lo);
      sonine_mass += son * (hi - lo);
    }
    // the first Sonine correction integrates to 0 (up to the range's tail)
    CHECK(sonine_mass == Approx(1.0).margin(1e-4));
    CHECK(counts <= 20000.0);
    CHECK(counts >= 19999.0);
    CHECK(hist_mass == Approx(counts / 20000.0).epsilon(1e-12));
    CHECK(mb_mass == Approx(1.0).margin(1e-6));
  }
  // The recorded values are those of an MB gas at kT = 2 (loose sanity bounds; the
  // statistics are tested in test_analysis_moments / _statistics): m2 = 6, kurtosis 3.
  CHECK(rec.column("m2")[2] == Approx(6.0).epsilon(0.05));
  CHECK(rec.column("kurtosis_x")[2] == Approx(3.0).epsilon(0.1));
  CHECK(rec.column("kT")[2] == Approx(2.0).epsilon(0.05));
  CHECK(rec.column("time")[1] == 0.5);
  CHECK_THROWS_AS(rec.column("nope"), InvalidInput);
  // A mixture adds per-species temperature columns; changing the species count is refused.
  MomentsRecorder mix;
  st.species.assign(st.size(), 0);
  for (std::size_t i = 0; i < st.size(); i += 2) st.species[i] = 1;
  st.species_inv_mass = {1.0, 0.5};
  mix.observe(st.snapshot());
  // the per-species columns come before the trailing a2, a3, T, real_time
  const std::vector<std::string> tail(mix.columns().end() - 6, mix.columns().end());
  CHECK(tail == std::vector<std::string>{"kT_0", "kT_1", "a2", "a3", "T", "real_time"});
  mix.write_speed_histogram_csv((dir.path / "h1.csv").string(), 1);
  CHECK(test::read_text(dir.path / "h1.csv").rfind("lo,hi,count,density,maxwell_density\n", 0) == 0);
  CHECK_THROWS_AS(mix.write_speed_histogram_csv((dir.path / "h2.csv").string(), 2), InvalidInput);
  st.species.clear();
  CHECK_THROWS_AS(mix.observe(st.snapshot()), InvalidInput);
}
