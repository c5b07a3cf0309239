// studies/src/report_parts.hpp -- the parts of the work-precision study (report.hpp):
// the fits, the error measure, and one function per study that appends its results.
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "hypergas/studies/report.hpp"

namespace hypergas::studies::detail {

/// Least-squares line y = a + b x: returns {b, standard error of b} (NaN for 2 points).
std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y);

/// Rate lambda of the least-squares fit y_k = A exp(-lambda t_k) (A eliminated exactly,
/// golden-section search on [lo, hi]).
double fit_decay_rate(const std::vector<double>& t, const std::vector<double>& y, double lo,
                      double hi);

/// Relative RMS of (x_r - ref)/ref over replicas and its standard error (~ rms / sqrt(2R)).
std::pair<double, double> rel_rms(const std::vector<double>& x, double ref);

/// Fits the slope of one curve of res.points, over its points with param <= max_param, and
/// appends it to res.slopes (nothing for fewer than 2 points).
void add_slope(ReportResult& res, const std::string& study, const std::string& engine, int dim,
               double max_param = std::numeric_limits<double>::infinity());

/// The studies of report.hpp; each appends its points, slopes and bias rows to `res`.
void stat_study(const ReportOptions& o, ReportResult& res);
void finite_n_study(const ReportOptions& o, ReportResult& res);
void maxwell_study(const ReportOptions& o, ReportResult& res);
void ntc_study(const ReportOptions& o, ReportResult& res);
void lanes_study(const ReportOptions& o, ReportResult& res);
void eos_study(const ReportOptions& o, ReportResult& res);
void schemes_study(const ReportOptions& o, ReportResult& res);

}  // namespace hypergas::studies::detail
