// Pair structure of the EDMD hard-sphere fluid (analysis/structure_recorder.hpp) against
// exact identities (docs/validation.md, "Structure of the hard-sphere fluid").
//
// Contact theorem: Z = 1 + 2^(D-1) eta g(sigma+) (edmd/observables.hpp), with Z from the
// collision virial and g(sigma+) extrapolated from the rdf, D = 2..6. The rdf's contact
// value carries the statistical error of its 16 stretches (Student t, 15 dof) and the
// extrapolation's systematic error, bounded by 0.5 % (the quadratic in ln g through 0.2
// sigma of bins: the difference between fits through 0.1 and 0.3 sigma, measured, is below
// 0.3 %). Z's own error is below a fifth of g's over the same run (blocks in
// test_edmd_eos.cpp). The check: |Z - 1 - 2^(D-1) eta g| <= 2^(D-1) eta (5 se + 0.005 g).
// Five se of t with 15 dof: two-sided 1.6e-4 each, 8e-4 for the five dimensions.
//
// Compressibility: S(k -> 0) = kT (dn/dp)_T = 1 / (d (eta Z) / d eta), from Carnahan-
// Starling (3D, accurate to 0.1 % in Z, ~1 % in S(0) at eta = 0.3) and Henderson (2D).
// S(0) is the intercept of a least-squares line in k^2 through the shells with k sigma <
// 1.6, fitted per stretch; the check allows 5 se plus 3 % for the equation of state and the
// curvature of S in k^2 the line leaves out.
//
// Large r: at a fixed number of particles g(r) tends to 1 + (1 - S(0)) / N, not 1
// (Lebowitz & Percus, Phys. Rev. 122, 1675 (1961)); its mean over r in [r_max - 1, r_max]
// equals that within 5 se (S(0) from Carnahan-Starling; the oscillations of g at 4-5 sigma
// and eta = 0.2 are below 1e-3 and average out over the interval).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hypergas/analysis/structure_recorder.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/edmd/observables.hpp"

using namespace hypergas;

namespace {

struct Structure {
  analysis::StructureResult r;
  double Z = 0.0;
  std::vector<std::vector<double>> s_stretches;
};

template <int D>
analysis::StructureResult measure(std::size_t n, double eta, double t_eq, double until,
                                  double every, double& Z, analysis::StructureSettings ss = {}) {
  edmd::Config cfg;
  cfg.n = n;
  cfg.packing = eta;
  cfg.seed = 21;
  edmd::Engine<D> e(cfg);
  e.run_until(t_eq);
  e.reset_observables();
  analysis::StructureRecorder rec(ss, D, n, t_eq);
  e.run_until(until, &rec, every);
  Z = e.pressure_Z();
  return rec.finish();
}

template <int D>
void check_contact(std::size_t n, double eta, double until, double every) {
  double Z = 0.0;
  analysis::StructureSettings ss;
  ss.k_max = 1.0;  // S(k) is not used here
  ss.r_max = 1.5;
  const analysis::StructureResult r = measure<D>(n, eta, 0.2 * until, until, every, Z, ss);
  const double c = std::pow(2.0, D - 1) * eta;
  INFO("D = " << D << " eta = " << eta << ": Z = " << Z << ", from the rdf "
              << 1.0 + c * r.contact << " (g(sigma+) = " << r.contact << " +- "
              << r.contact_error << ", from Z " << (Z - 1.0) / c << ")");
  CHECK(r.contact_error < 0.01 * r.contact);  // the check has power
  CHECK(std::fabs(Z - 1.0 - c * r.contact) <= c * (5.0 * r.contact_error + 0.005 * r.contact));
}

/// S(0) from the equation of state Z(eta): 1 / (d (eta Z) / d eta).
template <class Eos>
double s0(double eta, Eos z) {
  const double h = 1e-5;
  return 1.0 / (((eta + h) * z(eta + h) - (eta - h) * z(eta - h)) / (2.0 * h));
}

/// Intercept of the least-squares line S = a + b k^2 through the shells with k < k_fit.
double intercept(const std::vector<double>& k, const std::vector<double>& s, double k_fit) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (std::size_t i = 0; i < k.size() && k[i] < k_fit; ++i) {
    const double x = k[i] * k[i];
    sx += x, sy += s[i], sxx += x * x, sxy += x * s[i], m += 1;
  }
  const double b = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  return (sy - b * sx) / m;
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("contact theorem: Z from the virial equals 1 + 2^(D-1) eta g(sigma+) of "
                       "the rdf", "[edmd][physics][structure]", ((int D), D), 2, 3, 4, 5, 6) {
  if constexpr (D == 2) check_contact<2>(1000, 0.45, 200.0, 0.5);
  if constexpr (D == 3) check_contact<3>(1000, 0.30, 200.0, 0.5);
  if constexpr (D == 4) check_contact<4>(1500, 0.20, 100.0, 0.25);
  if constexpr (D == 5) check_contact<5>(1000, 0.12, 30.0, 0.1);
  if constexpr (D == 6) check_contact<6>(800, 0.08, 15.0, 0.05);
}

TEST_CASE("S(k -> 0) equals the compressibility of the equation of state (2D, 3D)",
          "[edmd][physics][structure]") {
  analysis::StructureSettings ss;
  ss.k_max = 3.0;
  ss.r_max = 2.0;
  const auto check = [&](const analysis::StructureResult& r, double expected) {
    const double a = intercept(r.k, r.s, 1.6);
    // the intercept's standard error from the shells' errors (independent shells)
    double se2 = 0;
    int m = 0;
    for (std::size_t i = 0; i < r.k.size() && r.k[i] < 1.6; ++i) se2 += r.s_error[i] * r.s_error[i], ++m;
    const double se = std::sqrt(se2) / m * 2.0;  // the intercept of a line: about twice the mean's
    INFO("S(0) fitted " << a << " +- " << se << ", from the equation of state " << expected
                        << "; shells below k = 1.6: " << m);
    CHECK(m >= 3);
    CHECK(std::fabs(a - expected) <= 5.0 * se + 0.03 * expected);
  };
  double Z = 0;
  check(measure<3>(4000, 0.30, 10.0, 60.0, 0.25, Z, ss), s0(0.30, edmd::carnahan_starling_Z));
  check(measure<2>(4000, 0.40, 10.0, 60.0, 0.25, Z, ss), s0(0.40, edmd::henderson_Z));
}

TEST_CASE("g(r) tends to 1 at large r", "[edmd][physics][structure]") {
  double Z = 0;
  const analysis::StructureResult r = measure<3>(1000, 0.20, 20.0, 100.0, 0.5, Z);
  double sum = 0, se2 = 0;
  int m = 0;
  for (std::size_t b = 0; b < r.r.size(); ++b)
    if (r.r[b] > r.r_max - 1.0) sum += r.g[b], se2 += r.g_error[b] * r.g_error[b], ++m;
  const double mean = sum / m, se = std::sqrt(se2) / m;
  INFO("mean g over the last sigma: " << mean << " +- " << se << " (" << m << " bins)");
  const double limit = 1.0 + (1.0 - s0(0.20, edmd::carnahan_starling_Z)) / 1000.0;
  INFO("finite-N limit " << limit);
  CHECK(std::fabs(mean - limit) <= 5.0 * se);
  CHECK(se < 0.005);
}
