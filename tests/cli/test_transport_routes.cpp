// One coefficient, one answer: `run --transport` reports each transport coefficient by one
// estimator (the plateau rule, analysis/src/integrals.hpp), and every run with two routes
// to a coefficient holds them against each other (summary keys
// <name>_route_difference_se, sim/outputs/route_check.hpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "cli/run_cli.hpp"

#ifdef HYPERGAS_CLI_PATH
namespace {

namespace fs = cli_test::fs;

using cli_test::json_number;

/// The CSV table `csv` as its header and rows of fields.
struct Table {
  std::vector<std::string> head;
  std::vector<std::vector<std::string>> rows;
  std::size_t at(const std::string& name) const {
    const auto i = std::find(head.begin(), head.end(), name);
    INFO("column " << name);
    REQUIRE(i != head.end());
    return static_cast<std::size_t>(i - head.begin());
  }
  /// Column `name` of the row whose first field is `key`.
  double cell(const std::string& key, const std::string& name) const {
    for (const auto& r : rows)
      if (r.front() == key) return std::strtod(r[at(name)].c_str(), nullptr);
    FAIL("no row " << key);
    return 0.0;
  }
  std::vector<double> column(const std::string& name) const {
    std::vector<double> v;
    for (const auto& r : rows) v.push_back(std::strtod(r[at(name)].c_str(), nullptr));
    return v;
  }
};

Table read(const fs::path& csv) {
  const auto lines = cli_test::lines(cli_test::slurp(csv));
  REQUIRE(lines.size() >= 2);
  Table t{cli_test::fields(lines.front()), {}};
  for (std::size_t i = 1; i < lines.size(); ++i) t.rows.push_back(cli_test::fields(lines[i]));
  return t;
}

}  // namespace

TEST_CASE("EDMD --transport: self-diffusion by the plateau rule equals the MSD slope, D = 2..6",
          "[cli][transport]") {
  // Each case: one run, the tagged particles' self-diffusion in transport.csv (Green-Kubo
  // and Einstein at the plateau of their running integrals, the tail's remainder added;
  // error = statistical (.) truncation) against the slope of the mean square displacement
  // of vacf.csv's 2000 particles over the second half of its lags,
  // D_msd = [msd(t2) - msd(t1)] / (2 D (t2 - t1)), an estimator with no cut at all. They
  // must agree within 3.5 stated errors: the MSD's own noise is left out of the tolerance,
  // and the truncation error is a bound (the whole remainder), so a false failure needs a
  // 3.5-sigma excursion, two-sided 5e-4 per case, 2.5e-3 for the five. Before (a cut at
  // three integral times and an exponential tail), 3D at packing 0.3 gave 0.1656 +- 0.0047
  // against an MSD slope of 0.191, and 4D 0.1150 +- 0.0016 against 0.133: 5 and 11 errors.
  // The routes' keys: Green-Kubo against Einstein, Green-Kubo against Einstein-Helfand
  // (viscosity, conductivity), each within 3 combined errors (both from one trajectory,
  // so their difference is far below that: a key above 3 is a defect).
  struct Case {
    int dim;
    const char* n;
    const char* packing;
    const char* until;
  };
  const Case cases[] = {{2, "4096", "0.4", "40"},
                        {3, "4000", "0.3", "40"},
                        {4, "4096", "0.2", "20"},
                        {5, "3125", "0.1", "20"},
                        {6, "4096", "0.05", "20"}};
  cli_test::Scratch s("routes");
  for (const Case& c : cases) {
    const auto out = s.path() / ("d" + std::to_string(c.dim));
    const auto res = cli_test::run({"run", "--engine", "edmd", "--dim", std::to_string(c.dim),
                                    "--n", c.n, "--packing", c.packing, "--until", c.until,
                                    "--transport", "--seed", "3", "--out", out.string()},
                                   s.path());
    INFO("D = " << c.dim << ": " << res.err);
    REQUIRE(res.code == 0);
    const Table tr = read(out / "transport.csv");
    const double ds = tr.cell("self_diffusion", "value");
    const double err = tr.cell("self_diffusion", "error");
    const double stat = tr.cell("self_diffusion", "statistical_error");
    const double trunc = tr.cell("self_diffusion", "truncation_error");
    // the stated error is its two parts
    CHECK(err == Approx(std::hypot(stat, trunc)).epsilon(1e-12));
    const Table v = read(out / "vacf.csv");
    const auto t = v.column("time"), m = v.column("msd");
    const std::size_t a = static_cast<std::size_t>(
        std::lower_bound(t.begin(), t.end(), 0.5 * t.back()) - t.begin());
    const std::size_t b = t.size() - 1;
    const double msd = (m[b] - m[a]) / (2.0 * c.dim * (t[b] - t[a]));
    INFO("self_diffusion " << ds << " +- " << err << " (statistical " << stat << ", truncation "
                           << trunc << "), MSD slope " << msd);
    CHECK(std::fabs(ds - msd) <= 3.5 * err);
    const std::string js = cli_test::slurp(out / "summary.json");
    for (const char* k : {"self_diffusion_route_difference_se",
                          "viscosity_route_difference_se",
                          "thermal_conductivity_route_difference_se"}) {
      INFO(k);
      CHECK(std::fabs(json_number(js, k)) <= 3.0);
    }
  }
}

TEST_CASE("DSMC --transport holds Green-Kubo against Einstein self-diffusion", "[cli][transport]") {
  // The Boltzmann gas's tagged particles: Green-Kubo of their velocities and the slope of
  // their exact virtual displacements, one trajectory, the key within 3 combined errors
  // (their difference is far below: a key above 3 is a defect).
  cli_test::Scratch s("routes-dsmc");
  const auto out = s.path() / "d";
  const auto res = cli_test::run({"run", "--engine", "dsmc", "--dim", "3", "--n", "1000",
                                  "--init", "maxwell", "--until", "1020", "--transport",
                                  "--out", out.string()},
                                 s.path());
  INFO(res.err);
  REQUIRE(res.code == 0);
  const double z =
      json_number(cli_test::slurp(out / "summary.json"), "self_diffusion_route_difference_se");
  CHECK(std::isfinite(z));
  CHECK(std::fabs(z) <= 3.0);
}

#endif
