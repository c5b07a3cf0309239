// Relaxation fit with gsl_multifit_nlinear.
#include "hypergas/analysis/fit.hpp"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "gsl_guard.hpp"
#include "hypergas/error.hpp"

namespace hypergas::analysis {

namespace {
struct Data {
  const std::vector<double>* t;
  const std::vector<double>* y;
  const std::vector<double>* sigma;
  bool fit_offset;
  double fixed_offset;
};

// Parameters p = (A, rate[, c]); residual r_i = (model - y_i) / sigma_i.
int residual(const gsl_vector* p, void* params, gsl_vector* r) {
  const auto& d = *static_cast<const Data*>(params);
  const double a = gsl_vector_get(p, 0), k = gsl_vector_get(p, 1);
  const double c = d.fit_offset ? gsl_vector_get(p, 2) : d.fixed_offset;
  for (std::size_t i = 0; i < d.t->size(); ++i) {
    const double s = d.sigma->empty() ? 1.0 : (*d.sigma)[i];
    gsl_vector_set(r, i, (a * std::exp(-k * (*d.t)[i]) + c - (*d.y)[i]) / s);
  }
  return GSL_SUCCESS;
}

int jacobian(const gsl_vector* p, void* params, gsl_matrix* j) {
  const auto& d = *static_cast<const Data*>(params);
  const double a = gsl_vector_get(p, 0), k = gsl_vector_get(p, 1);
  for (std::size_t i = 0; i < d.t->size(); ++i) {
    const double s = d.sigma->empty() ? 1.0 : (*d.sigma)[i];
    const double ti = (*d.t)[i], e = std::exp(-k * ti);
    gsl_matrix_set(j, i, 0, e / s);
    gsl_matrix_set(j, i, 1, -a * ti * e / s);
    if (d.fit_offset) gsl_matrix_set(j, i, 2, 1.0 / s);
  }
  return GSL_SUCCESS;
}

// Starting values: c from the tail (or fixed), rate from a log-linear least-squares line
// through the points with |y - c| above 5% of the initial excess.
void initial_guess(const Data& d, double& a, double& k, double& c) {
  const auto& t = *d.t;
  const auto& y = *d.y;
  const std::size_t n = t.size();
  if (d.fit_offset) {
    const std::size_t tail = std::max<std::size_t>(1, n / 10);
    c = 0.0;
    for (std::size_t i = n - tail; i < n; ++i) c += y[i];
    c /= static_cast<double>(tail);
  } else {
    c = d.fixed_offset;
  }
  a = y[0] - c;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = (y[i] - c) / a;
    if (!(e > 0.05)) continue;
    const double l = std::log(e);
    sx += t[i];
    sy += l;
    sxx += t[i] * t[i];
    sxy += t[i] * l;
    m += 1;
  }
  const double den = m * sxx - sx * sx;
  k = (m >= 2 && den > 0) ? -(m * sxy - sx * sy) / den : 0.0;
  if (!(k > 0.0) || !std::isfinite(k)) k = 1.0 / std::max(t[n - 1] - t[0], 1e-300);
  if (a == 0.0) a = 1e-12;
}
}  // namespace

RelaxationFit fit_relaxation(const std::vector<double>& t, const std::vector<double>& y,
                             const std::vector<double>& sigma, bool fit_offset,
                             double fixed_offset) {
  const std::size_t np = fit_offset ? 3 : 2;
  if (t.size() != y.size() || (!sigma.empty() && sigma.size() != y.size()))
    throw InvalidInput("fit_relaxation: t, y and sigma must have equal lengths");
  if (t.size() <= np)
    throw InvalidInput("fit_relaxation: need more than " + std::to_string(np) + " points, got " +
                       std::to_string(t.size()));
  for (std::size_t i = 0; i < t.size(); ++i)
    if (!std::isfinite(t[i]) || !std::isfinite(y[i]) ||
        (!sigma.empty() && !(sigma[i] > 0.0 && std::isfinite(sigma[i]))))
      throw InvalidInput("fit_relaxation: non-finite data or non-positive sigma at point " +
                         std::to_string(i));
  Data d{&t, &y, &sigma, fit_offset, fixed_offset};
  double a0, k0, c0;
  initial_guess(d, a0, k0, c0);

  detail::GslErrorGuard guard;
  gsl_multifit_nlinear_fdf fdf;
  fdf.f = residual;
  fdf.df = jacobian;
  fdf.fvv = nullptr;
  fdf.n = t.size();
  fdf.p = np;
  fdf.params = &d;
  gsl_multifit_nlinear_parameters fp = gsl_multifit_nlinear_default_parameters();
  gsl_multifit_nlinear_workspace* w =
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fp, fdf.n, fdf.p);
  if (!w) throw std::bad_alloc();
  gsl_vector* p = gsl_vector_alloc(np);
  gsl_matrix* cov = gsl_matrix_alloc(np, np);
  gsl_vector_set(p, 0, a0);
  gsl_vector_set(p, 1, k0);
  if (fit_offset) gsl_vector_set(p, 2, c0);
  int info = 0;
  int status = gsl_multifit_nlinear_init(p, &fdf, w);
  if (status == GSL_SUCCESS)
    status = gsl_multifit_nlinear_driver(500, 1e-10, 1e-10, 1e-12, nullptr, nullptr, &info, w);
  RelaxationFit r;
  if (status == GSL_SUCCESS) {
    gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, cov);
    double chi = 0.0;
    gsl_blas_ddot(gsl_multifit_nlinear_residual(w), gsl_multifit_nlinear_residual(w), &chi);
    r.chi2 = chi;
    r.dof = t.size() - np;
    const double scale = sigma.empty() ? r.chi2 / static_cast<double>(r.dof) : 1.0;
    const gsl_vector* x = gsl_multifit_nlinear_position(w);
    auto est = [&](std::size_t i) {
      return Estimate{gsl_vector_get(x, i), std::sqrt(scale * gsl_matrix_get(cov, i, i))};
    };
    r.amplitude = est(0);
    r.rate = est(1);
    r.offset = fit_offset ? est(2) : Estimate{fixed_offset, 0.0};
    r.tau = {1.0 / r.rate.value, r.rate.error / (r.rate.value * r.rate.value)};
    r.iterations = gsl_multifit_nlinear_niter(w);
  }
  gsl_matrix_free(cov);
  gsl_vector_free(p);
  gsl_multifit_nlinear_free(w);
  if (status != GSL_SUCCESS)
    throw InvalidInput(std::string("fit_relaxation: the fit did not converge (") +
                       gsl_strerror(status) + ")");
  if (!std::isfinite(r.rate.value) || !std::isfinite(r.rate.error))
    throw InvalidInput("fit_relaxation: the data do not determine a rate (flat or not decaying)");
  return r;
}

double line_slope(const std::vector<double>& x, const std::vector<double>& y, std::size_t b,
                  std::size_t e, const std::vector<double>& w) {
  const auto wt = [&](std::size_t i) { return w.empty() ? 1.0 : w[i]; };
  double sw = 0.0, sx = 0.0, sy = 0.0;
  for (std::size_t i = b; i < e; ++i) sw += wt(i), sx += wt(i) * x[i], sy += wt(i) * y[i];
  const double mx = sx / sw, my = sy / sw;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = b; i < e; ++i) {
    sxy += wt(i) * (x[i] - mx) * (y[i] - my);
    sxx += wt(i) * (x[i] - mx) * (x[i] - mx);
  }
  return sxx > 0.0 ? sxy / sxx : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace hypergas::analysis
