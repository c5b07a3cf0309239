// Maxwell–Boltzmann reference densities in D = 1..6 (analysis/maxwell.hpp): normalisation,
// consistency of pdf, cdf and quantile, and the known moments <v^2> = D kT/m,
// <v^4> = D(D+2)(kT/m)^2 (Cercignani 1988, ch. II; chi distribution with D degrees of freedom).
// Deterministic: numerical quadrature (GSL QAGI/QAGS) at relative tolerance 1e-10.
#include <catch2/catch.hpp>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <functional>

#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/error.hpp"

using namespace hypergas;
using namespace hypergas::analysis;

namespace {
// Integral of f over [lo, inf) (lo finite) or (-inf, inf) (lo = -inf).
double integrate(const std::function<double(double)>& f, double lo) {
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
  gsl_function g;
  g.function = [](double x, void* p) {
    return (*static_cast<const std::function<double(double)>*>(p))(x);
  };
  g.params = const_cast<std::function<double(double)>*>(&f);
  double r = 0, err = 0;
  if (std::isinf(lo))
    gsl_integration_qagi(&g, 1e-13, 1e-11, 1000, w, &r, &err);
  else
    gsl_integration_qagiu(&g, lo, 1e-13, 1e-11, 1000, w, &r, &err);
  gsl_integration_workspace_free(w);
  return r;
}
}  // namespace

TEST_CASE("MB reference densities integrate to 1 and have the known moments", "[analysis]") {
  const double kT = 1.7, mass = 0.6, a = kT / mass;
  for (int d = 1; d <= 6; ++d) {
    for (Quantity q : {Quantity::speed, Quantity::component, Quantity::energy}) {
      INFO("D = " << d << ", quantity " << to_string(q));
      const MaxwellReference r{q, d, kT, mass};
      const double lo = q == Quantity::component ? -INFINITY : 0.0;
      const auto mom = [&](int k) {
        return integrate([&](double x) { return std::pow(x, k) * r.pdf(x); }, lo);
      };
      CHECK(mom(0) == Approx(1.0).epsilon(1e-9));
      for (int k = 1; k <= 6; ++k) CHECK(mom(k) == Approx(r.moment(k)).epsilon(1e-8).margin(1e-12));
      if (q == Quantity::speed) {
        CHECK(r.moment(2) == Approx(d * a).epsilon(1e-14));
        CHECK(r.moment(4) == Approx(d * (d + 2.0) * a * a).epsilon(1e-14));
        CHECK(r.moment(6) == Approx(d * (d + 2.0) * (d + 4.0) * a * a * a).epsilon(1e-14));
      } else if (q == Quantity::component) {
        CHECK(r.moment(2) == Approx(a).epsilon(1e-15));
        CHECK(r.moment(4) == Approx(3 * a * a).epsilon(1e-15));
      } else {
        CHECK(r.moment(1) == Approx(0.5 * d * kT).epsilon(1e-14));  // equipartition
      }
      // cdf is the integral of pdf, and quantile inverts cdf.
      for (double p : {1e-6, 0.1, 0.5, 0.9, 1 - 1e-6}) {
        const double x = r.quantile(p);
        CHECK(r.cdf(x) == Approx(p).epsilon(1e-9));
        CHECK(r.upper_tail(x) == Approx(1 - p).epsilon(1e-9));
        const double from = q == Quantity::component ? r.quantile(1e-12) : 0.0;
        gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
        gsl_function g;
        g.function = [](double y, void* rp) {
          return static_cast<const MaxwellReference*>(rp)->pdf(y);
        };
        g.params = const_cast<MaxwellReference*>(&r);
        double val = 0, err = 0;
        gsl_integration_qags(&g, from, x, 1e-14, 1e-11, 1000, w, &val, &err);
        gsl_integration_workspace_free(w);
        CHECK(val ==
              Approx(p - (q == Quantity::component ? 1e-12 : 0.0)).epsilon(1e-8).margin(1e-13));
      }
    }
  }
}

TEST_CASE("MB reference: D = 1 speed is half-normal, D = 3 speed is Maxwell's", "[analysis]") {
  const MaxwellReference one{Quantity::speed, 1, 2.0, 1.0};
  CHECK(one.pdf(0.0) == Approx(std::sqrt(2.0 / (M_PI * 2.0))).epsilon(1e-15));
  const MaxwellReference three{Quantity::speed, 3, 1.0, 1.0};
  // f(v) = sqrt(2/pi) v^2 exp(-v^2/2) for kT/m = 1.
  for (double v : {0.1, 1.0, 2.5, 6.0})
    CHECK(three.pdf(v) ==
          Approx(std::sqrt(2 / M_PI) * v * v * std::exp(-0.5 * v * v)).epsilon(1e-14));
}

TEST_CASE("MB reference CDFs agree with GSL's chi-square and gamma CDFs", "[analysis]") {
  // maxwell.cpp evaluates P(D/2, x) and Q(D/2, x) by its own series / closed forms; GSL's
  // gsl_cdf_chisq_P/Q and gsl_cdf_gamma_P/Q are the reference (both ~1e-15 relative).
  for (int d = 1; d <= 12; ++d) {
    const MaxwellReference speed{Quantity::speed, d, 1.0, 1.0};
    const MaxwellReference energy{Quantity::energy, d, 2.0, 1.0};
    for (double u = 1e-4; u < 12.0; u *= 1.07) {
      INFO("D = " << d << " u = " << u);
      CHECK(speed.cdf(u) == Approx(gsl_cdf_chisq_P(u * u, d)).epsilon(1e-12));
      CHECK(speed.upper_tail(u) == Approx(gsl_cdf_chisq_Q(u * u, d)).epsilon(1e-12));
      CHECK(energy.cdf(u) == Approx(gsl_cdf_gamma_P(u, 0.5 * d, 2.0)).epsilon(1e-12));
      CHECK(energy.upper_tail(u) == Approx(gsl_cdf_gamma_Q(u, 0.5 * d, 2.0)).epsilon(1e-12));
    }
  }
}

TEST_CASE("MB reference rejects bad parameters", "[analysis]") {
  CHECK_THROWS_AS((MaxwellReference{Quantity::speed, 0, 1.0, 1.0}.validate()), InvalidInput);
  CHECK_THROWS_AS((MaxwellReference{Quantity::speed, 3, -1.0, 1.0}.validate()), InvalidInput);
  CHECK_THROWS_AS((MaxwellReference{Quantity::speed, 3, 1.0, NAN}.validate()), InvalidInput);
  CHECK_THROWS_AS((MaxwellReference{Quantity::speed, 3, 1.0, 1.0}.quantile(1.0)), InvalidInput);
}

TEST_CASE("First Sonine speed density: normalised, with <v^4> = (1 + a2) D(D+2) (kT/m)^2",
          "[analysis]") {
  // Sum over bins of width 0.01 up to 12 sqrt(kT/m) (Simpson within each bin): the
  // S2 term integrates to 0 against the Maxwellian and adds a2 D(D+2) (kT/m)^2 to <v^4>.
  for (const int d : {2, 3, 6}) {
    const hypergas::analysis::MaxwellReference ref{hypergas::analysis::Quantity::speed, d, 1.7, 2.0};
    const double a2 = 0.1, w = 0.01 * std::sqrt(ref.kT / ref.mass);
    double norm = 0.0, m4 = 0.0, plain = 0.0;
    for (int i = 0; i < 1200; ++i) {
      const double lo = i * w, hi = lo + w, v = lo + 0.5 * w;
      const double f = hypergas::analysis::sonine_bin_density(ref, a2, lo, hi);
      norm += f * w;
      m4 += f * w * v * v * v * v;
      plain += hypergas::analysis::sonine_bin_density(ref, 0.0, lo, hi) * w;
    }
    const double t = ref.kT / ref.mass;
    CHECK(norm == Approx(1.0).epsilon(1e-6));
    CHECK(plain == Approx(1.0).epsilon(1e-6));
    // midpoint moments of bins of 0.01: relative error ~ (w/v)^2, 1e-4
    CHECK(m4 == Approx((1.0 + a2) * d * (d + 2) * t * t).epsilon(1e-3));
  }
}
