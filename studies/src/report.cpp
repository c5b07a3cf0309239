// The work-precision study (report.hpp): the order of the studies, the files, the summary.
#include "hypergas/studies/report.hpp"

#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <system_error>

#include "hypergas/analysis/output.hpp"
#include "hypergas/error.hpp"
#include "hypergas/studies/gnuplot.hpp"
#include "report_parts.hpp"

namespace hypergas::studies {

namespace {

/// printf-style formatting into a std::string.
[[gnu::format(printf, 1, 2)]] std::string format(const char* fmt, ...) {
  std::va_list args, copy;
  va_start(args, fmt);
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, fmt, copy);
  va_end(copy);
  std::string s(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(s.data(), s.size() + 1, fmt, args);
  va_end(args);
  return s;
}

/// The studies' one CSV writer: `header`, then `rows` (each a formatted line without its
/// newline), written atomically (analysis/output.hpp).
void write_csv(const std::filesystem::path& file, const std::string& header,
               const std::vector<std::string>& rows) {
  analysis::write_file_atomic(file.string(), [&](std::ostream& os) {
    os << header << '\n';
    for (const auto& r : rows) os << r << '\n';
  });
}

std::vector<std::string> bias_rows(const std::vector<BiasRow>& rows) {
  std::vector<std::string> out;
  for (const auto& b : rows)
    out.push_back(format("%d,%.10g,%.6e,%.3e,%.6e", b.dim, b.param, b.bias, b.bias_se, b.theory));
  return out;
}

/// Which NTC steps show a bias beyond 3 standard errors (ntc_study's detection rule).
struct NtcDetection {
  int count = 0;          ///< rows with |bias| > 3 se
  double max_sig = 0.0;   ///< the largest |bias| / se
  double max_sig_dt = 0;  ///< its dt
};
NtcDetection ntc_detection(const ReportResult& res) {
  NtcDetection d;
  for (const auto& b : res.ntc) {
    if (!(b.bias_se > 0)) continue;
    const double sig = std::abs(b.bias) / b.bias_se;
    if (sig > 3.0) ++d.count;
    if (sig > d.max_sig) d.max_sig = sig, d.max_sig_dt = b.param;
  }
  return d;
}

}  // namespace

std::string scheme_label(const SchemePoint& p) {
  if (p.scheme == "ntc") return format("ntc dt = %g", p.dt);
  return p.scheme;
}

Recommendation recommend(const std::vector<SchemePoint>& points, double target) {
  Recommendation r;
  r.target = target;
  for (const auto& p : points)
    if (p.error <= target && (!r.found || p.run_s < r.point.run_s)) {
      r.found = true;
      r.point = p;
    }
  return r;
}

std::string schemes_recommendation(const std::vector<SchemePoint>& points) {
  std::string s;
  if (points.empty()) return s;
  for (double e : recommendation_targets) {
    const Recommendation r = recommend(points, e);
    if (r.found) {
      // The fastest point of another scheme that reaches e: the margin of the choice.
      std::vector<SchemePoint> others;
      for (const auto& p : points)
        if (p.scheme != r.point.scheme) others.push_back(p);
      const Recommendation next = recommend(others, e);
      s += format("for relative error %.0e within time %.3g s use %s (N = %.0f", e,
                  r.point.run_s, scheme_label(r.point).c_str(), r.point.n);
      if (next.found)
        s += format("; next: %s, %.3g s at N = %.0f", scheme_label(next.point).c_str(),
                    next.point.run_s, next.point.n);
      s += ")\n";
    } else
      s += format("for relative error %.0e: no measured run reaches it\n", e);
  }
  return s;
}

ReportResult run_report_study(const ReportOptions& o) {
  if (o.threads < 1 || o.threads > 64) throw InvalidInput("report: threads must be in 1..64");
  const auto wall0 = std::chrono::steady_clock::now();
  auto say = [&](const char* s) {
    if (o.verbose) std::fprintf(stderr, "report: %s\n", s);
  };
  ReportResult res;
  say("statistical error of the equilibrium <(m v^2/kT)^2>, D = 1..6");
  detail::stat_study(o, res);
  say("finite-N bias: N = 200 in 3D against Maxwell-Boltzmann, and bias against N");
  detail::finite_n_study(o, res);
  say("Maxwell-molecule fourth-moment rate, D = 2..6");
  detail::maxwell_study(o, res);
  say("NTC time-step bias against the exact process, 3D hard spheres");
  detail::ntc_study(o, res);
  say("lanes scheme bias and cost against the exact process, 3D hard spheres");
  detail::lanes_study(o, res);
  say("EDMD pressure Z against Tonks (1D), Henderson (2D), Carnahan-Starling (3D), virial (4D)");
  detail::eos_study(o, res);
  say("the choice of scheme: exact, NTC and lanes at N = 1e4, 1e5, 1e6, 3D hard spheres");
  detail::schemes_study(o, res);
  res.total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

void write_report(const ReportResult& res, const std::filesystem::path& dir, bool plot) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InvalidInput("report: cannot create output folder " + dir.string());
  std::vector<std::string> rows;
  for (const auto& p : res.points)
    rows.push_back(format("%s,%s,%d,%.10g,%.6e,%.6e,%.3e,%d", p.study.c_str(), p.engine.c_str(),
                          p.dim, p.param, p.run_s, p.error, p.error_se, p.replicas));
  write_csv(dir / "work_precision.csv", "study,engine,dim,param,run_s,error,error_se,replicas",
            rows);
  rows.clear();
  for (const auto& s : res.slopes)
    rows.push_back(format("%s,%s,%d,%.4f,%.4f,%d", s.study.c_str(), s.engine.c_str(), s.dim,
                          s.slope, s.slope_se, s.points));
  write_csv(dir / "slopes.csv", "study,engine,dim,slope,slope_se,points", rows);
  write_csv(dir / "finite_n.csv", "dim,n,rel_bias,rel_bias_se,theory", bias_rows(res.finite_n));
  write_csv(dir / "ntc.csv", "dim,dt,rel_bias,rel_bias_se,theory", bias_rows(res.ntc));
  rows.clear();
  for (std::size_t k = 0; k < res.lanes.size(); ++k)
    rows.push_back(format("%d,%.10g,%.6e,%.6e,%.6e,%.6e", res.lanes[k].dim, res.lanes[k].param,
                          res.lanes[k].bias, res.lanes[k].bias_se, res.lanes_run_s[k],
                          res.exact_run_s));
  write_csv(dir / "lanes.csv", "dim,lane_size,rel_bias,rel_bias_se,run_s,exact_run_s", rows);
  rows.clear();
  for (const auto& p : res.schemes)
    rows.push_back(format("%s,%.10g,%.10g,%.6e,%.6e,%.3e,%d", p.scheme.c_str(), p.dt, p.n,
                          p.run_s, p.error, p.error_se, p.replicas));
  write_csv(dir / "schemes.csv", "scheme,dt,n,run_s,error,error_se,replicas", rows);
  analysis::write_file_atomic((dir / "recommendation.txt").string(), [&](std::ostream& os) {
    os << schemes_recommendation(res.schemes);
  });
  // Slope variables for the gnuplot titles.
  const NtcDetection det = ntc_detection(res);
  analysis::write_file_atomic((dir / "slopes.gp").string(), [&](std::ostream& os) {
    for (const auto& s : res.slopes)
      os << format("slope_%s_%s_%d = %.3f\n", s.study.c_str(), s.engine.c_str(), s.dim, s.slope);
    os << format("ntc_order = %.3f\n", std::isnan(res.ntc_order) ? -99.0 : res.ntc_order);
    os << format("ntc_detected = %d\nntc_max_sig = %.2f\nntc_max_sig_dt = %.10g\n", det.count,
                 det.max_sig, det.max_sig_dt);
  });
  analysis::write_file_atomic((dir / "plot_report.gp").string(),
                              [&](std::ostream& os) { os << report_plot_script(); });
  if (plot) run_gnuplot(report_plot_script(), dir);
}

std::string report_summary(const ReportResult& res) {
  std::string s = format("%-10s %-6s %3s %8s %8s\n", "study", "engine", "D", "slope", "+-");
  for (const auto& r : res.slopes)
    s += format("%-10s %-6s %3d %8.3f %8.3f\n", r.study.c_str(), r.engine.c_str(), r.dim, r.slope,
                r.slope_se);
  const NtcDetection det = ntc_detection(res);
  if (!std::isnan(res.ntc_order))
    s += format("NTC step bias order: %.2f +- %.2f\n", res.ntc_order, res.ntc_order_se);
  else if (det.count > 0)
    s += format("NTC step bias: detected at %d dt only (largest %.1f se at dt = %g), no order"
                " fitted, see ntc.csv\n", det.count, det.max_sig, det.max_sig_dt);
  else if (!res.ntc.empty())
    s += "NTC step bias: not detectable at any dt (|bias| < 3 se), see ntc.csv\n";
  if (!res.schemes.empty()) {
    s += "scheme choice (kurtosis at t = 2, 3D hard spheres, one run; schemes.csv):\n";
    s += schemes_recommendation(res.schemes);
  }
  return s;
}

int run_report(const ReportOptions& o) {
  const ReportResult res = run_report_study(o);
  write_report(res, o.out, o.plot);
  std::fputs(report_summary(res).c_str(), stdout);
  std::printf("report written to %s in %.1f s\n", o.out.c_str(), res.total_s);
  return 0;
}

}  // namespace hypergas::studies
