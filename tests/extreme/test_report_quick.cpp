// The quick error-against-run-time report (hypergas/studies/report.hpp, `hypergas report
// --quick`): the CSV files have the documented shape, every error is finite and positive,
// the statistical error falls as run time^(-1/2), and the finite-N bias matches the exact
// microcanonical value, the scheme comparison's recommendation follows from its measured
// points and every measured error has an error bar. Also checks that the script written
// into the folder is scripts/plot_report.gp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hypergas/studies/report.hpp"

namespace {
std::vector<std::string> lines(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}
int fields(const std::string& l) { return 1 + static_cast<int>(std::count(l.begin(), l.end(), ',')); }
std::vector<std::string> split(const std::string& l) {
  std::vector<std::string> out;
  std::stringstream ss(l);
  for (std::string f; std::getline(ss, f, ',');) out.push_back(f);
  return out;
}
std::string text_of(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("hypergas report --quick: CSV shape and the statistical slope -1/2", "[report]") {
  hypergas::studies::ReportOptions o;
  o.quick = true;
  o.verbose = false;
  o.seed = 7;
  const auto res = hypergas::studies::run_report_study(o);
  const auto dir = std::filesystem::temp_directory_path() / "hypergas_report_quick_test";
  std::filesystem::remove_all(dir);
  hypergas::studies::write_report(res, dir, false);

  const auto wp = lines(dir / "work_precision.csv");
  REQUIRE(wp.at(0) == "study,engine,dim,param,run_s,error,error_se,replicas");
  // 6 dims x 4 run lengths (stat) + 4 (finite_n) + 5 dims x 3 sizes (maxwell) + 4 dims x 3
  // EDMD window lengths (eos).
  REQUIRE(wp.size() == 1 + 24 + 4 + 15 + 12);  // stat, finite_n, maxwell, eos
  for (std::size_t k = 1; k < wp.size(); ++k) REQUIRE(fields(wp[k]) == 8);
  for (const auto& p : res.points) {
    REQUIRE(std::isfinite(p.error));
    REQUIRE(p.error > 0.0);
    REQUIRE(p.run_s > 0.0);
  }
  const auto sl = lines(dir / "slopes.csv");
  REQUIRE(sl.at(0) == "study,engine,dim,slope,slope_se,points");
  REQUIRE(sl.size() == 1 + 6 + 5 + 4);
  REQUIRE(lines(dir / "finite_n.csv").size() == 1 + 10);
  REQUIRE(lines(dir / "ntc.csv").size() == 1 + 5);
  REQUIRE(lines(dir / "lanes.csv").size() == 1 + 4);
  // The lanes scheme at M = 4096 (N = 10000, 2 lanes): its kurtosis bias is O(1/M) ~ 1e-4
  // by the Maxwell-molecule law (docs/validation.md), far below the ~3e-3 resolution of 64
  // replicas, so it must be 0 within 4 se (false failure 6e-5).
  REQUIRE(res.lanes.size() == 4);
  INFO("lanes M = 4096: bias " << res.lanes.back().bias << " +- " << res.lanes.back().bias_se);
  CHECK(std::abs(res.lanes.back().bias) < 4.0 * res.lanes.back().bias_se);
  for (double s : res.lanes_run_s) CHECK(s > 0.0);

  // Statistical slope: the mean of the six per-D slopes (each with standard error ~0.03
  // from the scatter of 4 points about its line; mean ~0.013) within 0.1 of -1/2: a
  // deviation of > 7 standard errors, false-failure probability < 1e-10 if the slope is
  // -1/2. Each single slope within 0.25 (> 5 standard errors).
  double sum = 0.0;
  int n = 0;
  for (const auto& s : res.slopes)
    if (s.study == "stat") {
      INFO("D = " << s.dim << ": slope " << s.slope << " +- " << s.slope_se);
      CHECK(std::abs(s.slope + 0.5) < 0.25);
      sum += s.slope;
      ++n;
    }
  REQUIRE(n == 6);
  INFO("mean statistical slope " << sum / n);
  REQUIRE(std::abs(sum / n + 0.5) < 0.1);

  // EDMD pressure against Henderson (2D), Carnahan-Starling (3D) and the virial series (4D):
  // windows of 0.25, 1, 4 time units (16 replicas each) are in the statistical regime
  // (errors ~1e-2 to 3e-3, at or above the floors of <= 3e-3), so each slope is -1/2 up to
  // the scatter of three RMS errors from 16 replicas (relative standard error ~18 % per
  // point, 0.08 in log10, over a run-time span of 1.2 decades: slope standard error ~0.1; a
  // floor pulls it towards 0 by up to ~0.1). Each slope within 0.45 of -1/2 (3.5 se beyond
  // the pull: ~5e-4 each), their mean within 0.25 (mean se ~0.06: ~2.5 se beyond the pull,
  // ~1e-2); false failure ~1e-2 in all.
  // 1D is different: equal rods only exchange velocities, so the gas is N free points in
  // the free length L - N sigma (integrable); the number of collisions in a window is fixed
  // up to end effects, which add a 1/T term, and the error falls at least as fast as
  // T^(-1/2) (slopes -0.6 to -0.8 measured): checked within [-1.3, -0.35].
  double eos_sum = 0.0;
  int eos_n = 0;
  bool eos1 = false;
  for (const auto& s : res.slopes)
    if (s.study == "eos") {
      INFO("EDMD Z slope, D = " << s.dim << ": " << s.slope << " +- " << s.slope_se);
      if (s.dim == 1) {
        CHECK(s.slope < -0.35);
        CHECK(s.slope > -1.3);
        eos1 = true;
        continue;
      }
      CHECK(std::abs(s.slope + 0.5) < 0.45);
      eos_sum += s.slope;
      ++eos_n;
    }
  REQUIRE(eos1);
  REQUIRE(eos_n == 3);
  INFO("mean EDMD slope, D = 2..4: " << eos_sum / eos_n);
  REQUIRE(std::abs(eos_sum / eos_n + 0.5) < 0.25);

  // Finite-N bias against the exact microcanonical prediction: within 5 standard errors
  // + 2 % of the bias (the O(1) relative accuracy of its error estimate from 8 replicas).
  for (const auto& b : res.finite_n) {
    INFO("D = " << b.dim << ", N = " << b.param << ": bias " << b.bias << " +- " << b.bias_se
                << ", exact " << b.theory);
    REQUIRE(std::abs(b.bias - b.theory) < 5.0 * b.bias_se + 0.02 * std::abs(b.theory));
  }

  // Error bars: every measured error of work_precision.csv has a positive standard error.
  for (std::size_t k = 1; k < wp.size(); ++k) {
    const double se = std::stod(split(wp[k]).at(6));
    INFO(wp[k]);
    REQUIRE(std::isfinite(se));
    REQUIRE(se > 0.0);
  }

  // The scheme comparison: exact, NTC dt = 2, NTC dt = 0.5, lanes at N = 1e4, 1e5, 1e6.
  const auto sc = lines(dir / "schemes.csv");
  REQUIRE(sc.at(0) == "scheme,dt,n,run_s,error,error_se,replicas");
  REQUIRE(sc.size() == 1 + 4 * 3);
  struct Row {
    std::string scheme;
    double dt, n, run_s, error, error_se;
  };
  std::vector<Row> rows;
  for (std::size_t k = 1; k < sc.size(); ++k) {
    const auto f = split(sc[k]);
    REQUIRE(f.size() == 7);
    rows.push_back({f[0], std::stod(f[1]), std::stod(f[2]), std::stod(f[3]), std::stod(f[4]),
                    std::stod(f[5])});
    INFO(sc[k]);
    REQUIRE(rows.back().run_s > 0.0);
    REQUIRE(rows.back().error > 0.0);
    REQUIRE(std::isfinite(rows.back().error_se));
    REQUIRE(rows.back().error_se > 0.0);
  }
  auto row = [&](const std::string& scheme, double dt, double n) {
    for (const auto& r : rows)
      if (r.scheme == scheme && r.dt == dt && r.n == n) return r;
    FAIL("no schemes.csv row " << scheme << " dt " << dt << " N " << n);
    return rows.front();
  };
  // Physics of the points: one run's error of the exact scheme falls as N^(-1/2), a factor
  // 10 from 1e4 to 1e6. The RMS errors from 16 and 6 runs have relative standard errors of
  // 18 % and 32 %, so the log of the ratio has sd ~0.37: [2.5, 40] is 3.7 sd either way
  // (false failure ~2e-4). NTC at dt = 2 has a kurtosis bias of ~1.4e-3 (ntc.csv, full
  // report) against the exact scheme's one-run error of ~4.5e-4 at N = 1e6: its error
  // levels off above the exact one (difference ~1e-3, ~3.3 sd of the two estimates from 6
  // runs each: false failure ~5e-4).
  const double fall = row("exact", 0, 1e4).error / row("exact", 0, 1e6).error;
  INFO("exact: one-run error 1e4 / 1e6 = " << fall);
  CHECK(fall > 2.5);
  CHECK(fall < 40.0);
  INFO("NTC dt = 2 at 1e6: " << row("ntc", 2, 1e6).error << ", exact "
                             << row("exact", 0, 1e6).error);
  CHECK(row("ntc", 2, 1e6).error > row("exact", 0, 1e6).error);

  // The recommendation, recomputed from the CSV: for each target E the measured point with
  // error <= E and the least run time; the summary and recommendation.txt print it.
  const std::string summary = hypergas::studies::report_summary(res);
  const std::string rec = text_of(dir / "recommendation.txt");
  int found = 0;
  for (double e : hypergas::studies::recommendation_targets) {
    const Row* best = nullptr;
    for (const auto& r : rows)
      if (r.error <= e && (!best || r.run_s < best->run_s)) best = &r;
    char head[64];
    std::snprintf(head, sizeof head, "for relative error %.0e", e);
    std::string expect = head;
    if (best) {
      ++found;
      char label[64], tail[160];
      if (best->scheme == "ntc")
        std::snprintf(label, sizeof label, "ntc dt = %g", best->dt);
      else
        std::snprintf(label, sizeof label, "%s", best->scheme.c_str());
      std::snprintf(tail, sizeof tail, " within time %.3g s use %s (N = %.0f", best->run_s,
                    label, best->n);
      expect += tail;
    } else {
      expect += ": no measured run reaches it\n";
    }
    INFO("expected: " << expect << "\nsummary:\n" << summary);
    for (const std::string* t : {&summary, &rec}) {
      const std::size_t k = t->find(expect);
      REQUIRE(k != std::string::npos);
      // "(N = 10000" must not match "(N = 100000"; the line ends or names the next scheme.
      if (best) CHECK((t->substr(k + expect.size(), 2) == ")\n" ||
                       t->substr(k + expect.size(), 8) == "; next: "));
    }
  }
  // The loosest target, 1e-2, is above every one-run error at N >= 1e4 (~5e-3 at 1e4).
  REQUIRE(found >= 1);

  // The plot draws every measured error of work_precision.csv and schemes.csv with its
  // error bar (the file's standard error column).
  std::string gp = text_of(dir / "plot_report.gp");
  for (std::size_t k; (k = gp.find("\\\n")) != std::string::npos;) gp.erase(k, 2);
  int curves = 0;
  for (const std::string file : {"'work_precision.csv'", "'schemes.csv'"})
    for (std::size_t k = gp.find(file); k != std::string::npos; k = gp.find(file, k + 1)) {
      const std::string clause = gp.substr(k, gp.find("title", k) - k);
      INFO(clause);
      CHECK(clause.find("yerror") != std::string::npos);
      ++curves;
    }
  REQUIRE(curves >= 8);  // stat, finite_n, eos, maxwell; exact, 2 NTC, lanes
}

TEST_CASE("report: the folder's plot_report.gp is scripts/plot_report.gp", "[report]") {
  auto text = [](const std::filesystem::path& f) {
    std::ifstream in(f);
    REQUIRE(in.good());
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  const auto src = std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() /
                   "scripts" / "plot_report.gp";
  const auto dir = std::filesystem::temp_directory_path() / "hypergas_report_script_test";
  std::filesystem::remove_all(dir);
  hypergas::studies::write_report(hypergas::studies::ReportResult{}, dir, false);
  REQUIRE(text(dir / "plot_report.gp") == text(src));
}

TEST_CASE("report: the recommendation and the NTC title follow the measured points", "[report]") {
  using hypergas::studies::SchemePoint;
  hypergas::studies::ReportResult res;
  // exact is cheapest at 1e-2, NTC dt = 2 levels off at 2e-3 (its bias), lanes is cheaper
  // than exact at N = 1e6.
  res.schemes = {{"exact", 0, 1e4, 0.001, 5e-3, 1e-3, 16},
                 {"exact", 0, 1e6, 0.200, 5e-4, 1e-4, 6},
                 {"ntc", 2, 1e4, 0.0011, 6e-3, 1e-3, 16},
                 {"ntc", 2, 1e6, 0.150, 2e-3, 3e-4, 6},
                 {"lanes", 0, 1e4, 0.0012, 5e-3, 1e-3, 16},
                 {"lanes", 0, 1e6, 0.140, 6e-4, 1e-4, 6}};
  // NTC: only dt = 2 beyond 3 se (5 se): detected, no order fitted.
  res.ntc = {{3, 2.0, 1.5e-3, 3e-4, 0}, {3, 1.0, 2e-4, 3e-4, 0}, {3, 0.5, 1e-4, 3e-4, 0}};
  const std::string s = hypergas::studies::report_summary(res);
  INFO(s);
  CHECK(s.find("for relative error 1e-02 within time 0.001 s use exact (N = 10000; next: ntc dt "
               "= 2, 0.0011 s at N = 10000)\n") != std::string::npos);
  CHECK(s.find("for relative error 3e-03 within time 0.14 s use lanes (N = 1000000; next: ntc "
               "dt = 2, 0.15 s at N = 1000000)\n") != std::string::npos);
  CHECK(s.find("for relative error 1e-03 within time 0.14 s use lanes (N = 1000000; next: exact, "
               "0.2 s at N = 1000000)\n") != std::string::npos);
  CHECK(s.find("for relative error 5e-04 within time 0.2 s use exact (N = 1000000)\n") !=
        std::string::npos);
  CHECK(s.find("not detectable") == std::string::npos);
  CHECK(s.find("NTC step bias: detected at 1 dt only (largest 5.0 se at dt = 2)") !=
        std::string::npos);
  const auto dir = std::filesystem::temp_directory_path() / "hypergas_report_recommend_test";
  std::filesystem::remove_all(dir);
  hypergas::studies::write_report(res, dir, false);
  const std::string gp = text_of(dir / "slopes.gp");
  CHECK(gp.find("ntc_detected = 1\n") != std::string::npos);
  CHECK(gp.find("ntc_max_sig = 5.00\nntc_max_sig_dt = 2\n") != std::string::npos);
  CHECK(text_of(dir / "recommendation.txt").find("use lanes (N = 1000000") != std::string::npos);
}
