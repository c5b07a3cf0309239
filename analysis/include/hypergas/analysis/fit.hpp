// hypergas/analysis/fit.hpp -- relaxation-time fit y(t) = A exp(-t / tau) + c, and the
// least-squares slope of a straight line.
//
// Nonlinear least squares (GSL gsl_multifit_nlinear, Levenberg–Marquardt trust region). The
// parameter errors are the square roots of the covariance diagonal; without given sigmas
// the covariance is scaled by chi^2 / dof (the residual scatter estimates the noise).
#pragma once

#include <cstddef>
#include <vector>

#include "hypergas/analysis/moments.hpp"

namespace hypergas::analysis {

/// The result of fit_relaxation; time units are those of t.
struct RelaxationFit {
  Estimate amplitude;   ///< A, units of y
  Estimate rate;        ///< 1 / tau, 1/time
  Estimate tau;         ///< relaxation time, time (error propagated from the rate)
  Estimate offset;      ///< c, units of y (error 0 when held fixed)
  double chi2 = 0.0;    ///< weighted sum of squared residuals
  std::size_t dof = 0;  ///< points - fitted parameters
  std::size_t iterations = 0;
};

/// Fits y = A exp(-rate t) + c. `sigma` (optional, same length as y) are the standard errors
/// of y. With fit_offset = false, c is held at `fixed_offset` (e.g. 0 for a distance, 1 for
/// m4_ratio). Throws InvalidInput for mismatched or too short input or a failed fit. Data
/// that do not decay may still "converge": then rate.error exceeds |rate.value|.
RelaxationFit fit_relaxation(const std::vector<double>& t, const std::vector<double>& y,
                             const std::vector<double>& sigma = {}, bool fit_offset = true,
                             double fixed_offset = 0.0);

/// Least-squares slope of y against x over the points [b, e), weighted by w (empty: all
/// weights 1); units of y per unit of x. NaN if the x of the points do not vary.
double line_slope(const std::vector<double>& x, const std::vector<double>& y, std::size_t b,
                  std::size_t e, const std::vector<double>& w = {});

}  // namespace hypergas::analysis
