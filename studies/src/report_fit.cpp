// The fits and the error measure of the work-precision study.
#include <cmath>

#include "report_parts.hpp"

namespace hypergas::studies::detail {

std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  double sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  const double b = sxy / sxx;
  double rss = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double e = y[k] - my - b * (x[k] - mx);
    rss += e * e;
  }
  const double se = x.size() > 2 ? std::sqrt(rss / (n - 2.0) / sxx) : std::nan("");
  return {b, se};
}

double fit_decay_rate(const std::vector<double>& t, const std::vector<double>& y, double lo,
                      double hi) {
  auto resid = [&](double lam) {
    double se = 0, sye = 0, syy = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double e = std::exp(-lam * t[k]);
      se += e * e, sye += y[k] * e, syy += y[k] * y[k];
    }
    return syy - sye * sye / se;
  };
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo, b = hi, c = b - g * (b - a), d = a + g * (b - a);
  for (int it = 0; it < 100; ++it) {
    if (resid(c) < resid(d)) b = d;
    else a = c;
    c = b - g * (b - a), d = a + g * (b - a);
  }
  return 0.5 * (a + b);
}

std::pair<double, double> rel_rms(const std::vector<double>& x, double ref) {
  double s = 0;
  for (double v : x) s += (v - ref) * (v - ref);
  const double rms = std::sqrt(s / static_cast<double>(x.size())) / std::abs(ref);
  return {rms, rms / std::sqrt(2.0 * static_cast<double>(x.size()))};
}

void add_slope(ReportResult& res, const std::string& study, const std::string& engine, int dim,
               double max_param) {
  std::vector<double> x, y;
  for (const auto& p : res.points)
    if (p.study == study && p.engine == engine && p.dim == dim && p.error > 0 &&
        p.param <= max_param) {
      x.push_back(std::log10(p.run_s));
      y.push_back(std::log10(p.error));
    }
  if (x.size() < 2) return;
  const auto [b, se] = fit_line(x, y);
  res.slopes.push_back({study, engine, dim, b, se, static_cast<int>(x.size())});
}

}  // namespace hypergas::studies::detail
