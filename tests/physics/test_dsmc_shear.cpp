// Uniform shear flow in the DSMC engine (dsmc/shear.hpp; docs/validation.md, "Uniform shear
// flow"): Maxwell molecules against their exact rheology in D = 2..6 (dsmc/shear_theory.hpp),
// with and without the isokinetic thermostat; the exact finite-N mean of the transient; the
// thermostat's energy; and the reduction to the unsheared engine at a = 0.
//
// Statistics. A steady-state run of N = 1e5 samples P / p every 0.25 mean collision times
// over [40, 240] (the transient decays as exp(-r t) or faster, r ~ 1/2: e^-20 at t = 40); the
// 801 samples are cut into 20 blocks of 10 mean collision times (five stress relaxation
// times), and the error is the standard error of the 20 block means. A comparison passes
// within 5 standard errors: for a t-distribution with 19 degrees of freedom
// P(|t| > 5) = 8.0e-5, and the test case makes 58 comparisons, so it fails falsely with
// probability 4.6e-3 if the blocks were independent (they are nearly so: 10 mean collision
// times against a correlation time of 2). The test also requires each tolerance, 5 se, to
// be at most 0.5 % of the value compared: the precision the rheology is tested at. The
// shear rates are those where P_yy / p >= 0.5 (its absolute error is about the same at
// every a, so its relative error grows as P_yy falls: 3.5e-4 at this N and length).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hypergas/analysis/estimates.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/dsmc/shear_theory.hpp"
#include "hypergas/observer.hpp"

using namespace hypergas;

namespace {

/// Per sample: P_xx, P_xy, P_yy, P_zz (mean of the other axes) and P_xz over p (P = sum
/// m v v^T / (N - 1)); the true temperature; the real time.
struct Tensor final : Observer {
  double from = 0.0;
  std::vector<double> xx, xy, yy, zz, xz, T, real_time;
  void observe(const Snapshot& s) override {
    if (s.time < from) return;
    const int D = s.dim;
    double p[5] = {}, tr = 0.0;
    for (std::size_t i = 0; i < s.n; ++i) {
      const double* v = s.velocities + i * s.stride;
      const double m = 1.0 / s.inverse_mass(i);
      p[0] += m * v[0] * v[0], p[1] += m * v[0] * v[1], p[2] += m * v[1] * v[1];
      for (int k = 2; k < D; ++k) p[3] += m * v[k] * v[k];
      if (D > 2) p[4] += m * v[0] * v[2];
      for (int k = 0; k < D; ++k) tr += m * v[k] * v[k];
    }
    const double kT = tr / D;
    xx.push_back(p[0] / kT), xy.push_back(p[1] / kT), yy.push_back(p[2] / kT);
    zz.push_back(D > 2 ? p[3] / (D - 2) / kT : 0.0), xz.push_back(p[4] / kT);
    T.push_back(kT / (static_cast<double>(s.n) - 1.0) * std::exp(2.0 * s.log_velocity_scale));
    real_time.push_back(std::isnan(s.real_time) ? s.time : s.real_time);
  }
};

constexpr std::size_t n_blocks = 20;
constexpr double tolerance_se = 5.0;

analysis::MeanSe blocks(const std::vector<double>& y) {
  return analysis::block_average(y, 0, y.size(), n_blocks);
}

/// Compares a block estimate with an exact value: within 5 se, and (nonzero values) at a
/// precision of 0.5 % or better.
void check(const char* what, const analysis::MeanSe& m, double exact, bool precision = true) {
  INFO(what << ": " << m.mean << " +- " << m.se << " against " << exact);
  CHECK(std::abs(m.mean - exact) <= tolerance_se * m.se);
  if (precision) CHECK(tolerance_se * m.se <= 0.005 * std::abs(exact));
}

/// The steady state at shear rate a under thermostat th; alpha < 1 (no thermostat): the
/// granular gas, against maxwell_granular_shear.
template <int D>
void steady_maxwell(double a, dsmc::Thermostat th, double alpha = 1.0) {
  dsmc::Config c;
  c.n = 100000;
  c.init = InitialState::maxwell;
  c.seed = 17 + D;
  c.shear_rate = a;
  c.thermostat = th;
  c.restitution = alpha;
  dsmc::Engine<D, dsmc::MaxwellMolecules> e(c);
  Tensor t;
  t.from = 40.0;
  e.run_until(240.0, &t, 0.25);
  REQUIRE(t.xx.size() == 801);
  dsmc::MaxwellShear exact = dsmc::maxwell_shear(D, a, static_cast<double>(c.n));
  if (alpha < 1.0) {
    const auto g = dsmc::maxwell_granular_shear(D, a, alpha, static_cast<double>(c.n));
    exact.pxx = g.pxx, exact.pyy = g.pyy, exact.pzz = g.pzz, exact.pxy = g.pxy;
    exact.zeta = 0.5 * g.growth;
  }
  INFO("D = " << D << ", a = " << a << ", restitution " << alpha
              << (th == dsmc::Thermostat::isokinetic ? ", isokinetic" : ", no thermostat"));
  check("P_xx/p", blocks(t.xx), exact.pxx);
  check("P_yy/p", blocks(t.yy), exact.pyy);
  check("P_xy/p", blocks(t.xy), exact.pxy);
  if (D > 2) {
    check("P_zz/p", blocks(t.zz), exact.pzz);
    check("P_xz/p", blocks(t.xz), 0.0, false);
  }
  if (th == dsmc::Thermostat::isokinetic) {
    // the Gaussian thermostat holds the energy at every sample to rounding
    for (double T : t.T) REQUIRE(std::abs(T - t.T.front()) <= 1e-12 * T);
    std::vector<double> zeta;
    for (double x : t.xy) zeta.push_back(-a * x / D);
    check("thermostat rate", blocks(zeta), exact.zeta);
  } else {
    // heating: d ln T / dt per block, against 2 zeta
    const auto h = analysis::over_blocks(0, t.T.size() - 1, n_blocks, [&](std::size_t i, std::size_t j) {
      return std::log(t.T[j] / t.T[i]) / (t.real_time[j] - t.real_time[i]);
    });
    // (near the granular balance the rate is near 0: compared within 5 se, at an absolute
    // precision of 0.5 % of the elastic gas's rate at the same a)
    const double scale = 2.0 * dsmc::maxwell_shear(D, a, static_cast<double>(c.n)).zeta;
    INFO("heating rate: " << h.mean << " +- " << h.se << " against " << 2.0 * exact.zeta);
    CHECK(std::abs(h.mean - 2.0 * exact.zeta) <= tolerance_se * h.se);
    CHECK(tolerance_se * h.se <= 0.005 * scale);
  }
}

}  // namespace

TEST_CASE("Maxwell molecules in shear flow: exact rheology, D = 2..6", "[dsmc][shear]") {
  using enum dsmc::Thermostat;
  steady_maxwell<2>(0.5, isokinetic);
  steady_maxwell<2>(1.0, none);
  steady_maxwell<3>(0.5, none, 0.8);  // granular: growth +0.1004 (heating wins)
  steady_maxwell<3>(1.2, isokinetic);
  steady_maxwell<4>(0.5, isokinetic);
  steady_maxwell<4>(1.2, none);
  steady_maxwell<5>(0.45, none, 0.7);  // granular: growth -0.0033, near the balance
  steady_maxwell<5>(1.2, isokinetic);
  steady_maxwell<6>(0.5, isokinetic);
  steady_maxwell<6>(1.2, none);
}

TEST_CASE("Maxwell molecules in shear flow: the exact mean of the transient", "[dsmc][shear]") {
  // Without thermostat the mean of P = sum v v^T / (N - 1) obeys a linear law exactly at
  // every N (dsmc/shear_theory.hpp). 24 replicas of N = 4000 in 4D at a = 1.5: the replica
  // mean of P_ij(t) / T0 at t = 0.5, 1, 2, 4 against the law, within 4.5 se (t with 23 dof:
  // P(|t| > 4.5) = 1.6e-4 per comparison, 16 comparisons).
  constexpr int D = 4, R = 24;
  const double a = 1.5, times[] = {0.5, 1.0, 2.0, 4.0};
  std::vector<std::vector<double>> got(16);
  for (int r = 0; r < R; ++r) {
    dsmc::Config c;
    c.n = 4000;
    c.init = InitialState::maxwell;
    c.seed = 100 + r;
    c.shear_rate = a;
    dsmc::Engine<D, dsmc::MaxwellMolecules> e(c);
    const double T0 = e.temperature();
    for (int k = 0; k < 4; ++k) {
      e.run_until(times[k]);
      Tensor t;
      e.observe(t);
      const double T = t.T[0] / T0;
      got[4 * k + 0].push_back(t.xx[0] * T), got[4 * k + 1].push_back(t.xy[0] * T);
      got[4 * k + 2].push_back(t.yy[0] * T), got[4 * k + 3].push_back(t.zz[0] * T);
    }
  }
  for (int k = 0; k < 4; ++k) {
    const auto exact = dsmc::maxwell_shear_moments(D, a, 4000.0, times[k]);
    for (int c = 0; c < 4; ++c) {
      const analysis::MeanSe m = analysis::mean_se(got[4 * k + c]);
      INFO("t = " << times[k] << ", component " << c << ": " << m.mean << " +- " << m.se
                  << " against " << exact[c]);
      CHECK(std::abs(m.mean - exact[c]) <= 4.5 * m.se);
    }
  }
}

namespace {
/// The pathwise energy balance of an elastic sheared gas without thermostat: collisions
/// keep the energy, the flow changes it at d(sum m V^2)/dt = -2 a sum m V_x V_y, so
/// ln T(t) - ln T(0) = -(2 a / D) integral of P*_xy over real time, for every realisation.
/// The integral by the trapezoidal rule over samples 0.01 of real time apart.
template <int D, class Model, Features F = Features{}>
void energy_balance(dsmc::Config c) {
  dsmc::Engine<D, Model, F> e(c);
  Tensor t;
  double ln_t = 0.0, integral = 0.0;
  e.observe(t);
  while (e.real_time() < 8.0) {
    // the clock runs in collision times of the heating gas: steps of 0.01 in real time
    e.run_until(e.time() + 0.01 * std::pow(t.T.back() / t.T.front(), 0.5 * e.model().exponent()));
    e.observe(t);
    const std::size_t k = t.T.size() - 1;
    integral += 0.5 * (t.xy[k] + t.xy[k - 1]) * (t.real_time[k] - t.real_time[k - 1]);
  }
  ln_t = std::log(t.T.back() / t.T.front());
  const double predicted = -2.0 * c.shear_rate / D * integral;
  INFO("D = " << D << ", " << Model::name << ": ln T/T0 " << ln_t << " against " << predicted
              << " (" << t.T.size() << " samples)");
  CHECK(ln_t > 1.0);
  CHECK(std::abs(ln_t - predicted) <= 1e-3 * ln_t);
}
}  // namespace

TEST_CASE("Shear flow: the energy balance of hard spheres and VHS, path by path",
          "[dsmc][shear]") {
  dsmc::Config c;
  c.n = 5000;
  c.init = InitialState::maxwell;
  c.shear_rate = 1.5;
  energy_balance<3, dsmc::HardSpheres>(c);
  c.vhs_exponent = 0.3;
  energy_balance<5, dsmc::VariableHardSpheres>(c);
  c.initial.mass_ratio = 2.5;
  c.initial.fraction = 0.4;
  energy_balance<2, dsmc::HardSpheres, Features{.species = true}>(c);
}

TEST_CASE("Shear flow: the theory's closed forms", "[dsmc][shear]") {
  // the granular law at alpha = 1 is the elastic one; at the balance shear rate it is steady
  for (int d : {2, 3, 6})
    for (double a : {0.2, 1.0, 4.0}) {
      const auto e = dsmc::maxwell_shear(d, a, 1000.0);
      const auto g = dsmc::maxwell_granular_shear(d, a, 1.0, 1000.0);
      CHECK(g.growth == Approx(2.0 * e.zeta).epsilon(1e-12));
      CHECK(g.pxy == Approx(e.pxy).epsilon(1e-12));
      CHECK(g.pyy == Approx(e.pyy).epsilon(1e-12));
    }
  for (double alpha : {0.0, 0.5, 0.9}) {
    const double b = 0.5 * (1.0 + alpha), nu_p = 0.5 * b * (2.0 - b), nu_t = 0.5 * b * b;
    const double a = std::sqrt(3.0 * nu_p * nu_p * (nu_p - nu_t) / (2.0 * nu_t));
    CHECK(std::abs(dsmc::maxwell_granular_shear(3, a, alpha).growth) < 1e-13);
  }
  // 3D against the Garzo-Santos closed form zeta/r = (2/3) sinh^2[(1/6) arccosh(1 + 9 (a/r)^2)]
  for (double a : {0.1, 1.0, 5.0}) {
    const auto s = dsmc::maxwell_shear(3, a);
    const double r = 0.5, x = a / r;
    CHECK(s.zeta / r == Approx((2.0 / 3.0) * std::pow(std::sinh(std::acosh(1 + 9 * x * x) / 6), 2))
                            .epsilon(1e-12));
    // the trace, and the steady solution of the linear law's long-time ratios
    CHECK(s.pxx + 2 * s.pyy == Approx(3.0).epsilon(1e-14));
    const auto m = dsmc::maxwell_shear_moments(3, a, 0.0, 200.0 / (1 + a));
    const double T = (m[0] + m[2] + m[3]) / 3;
    CHECK(m[1] / T == Approx(s.pxy).epsilon(1e-6));
    CHECK(m[0] / T == Approx(s.pxx).epsilon(1e-6));
  }
  // a -> 0: Navier-Stokes, P_xy = -a / r
  CHECK(dsmc::maxwell_shear(5, 1e-4).pxy == Approx(-2e-4).epsilon(1e-6));
}

TEST_CASE("Shear flow: bad configurations are refused", "[dsmc][shear]") {
  dsmc::Config c;
  c.n = 100;
  c.init = InitialState::maxwell;
  const auto refused = [&](auto&& set) {
    dsmc::Config k = c;
    set(k);
    try {
      dsmc::Engine<3, dsmc::HardSpheres> e(k);
      return false;
    } catch (const InvalidInput&) {
      return true;
    }
  };
  CHECK(refused([](dsmc::Config& k) { k.shear_rate = -1.0; }));
  CHECK(refused([](dsmc::Config& k) { k.shear_rate = std::nan(""); }));
  CHECK(refused([](dsmc::Config& k) { k.shear_rate = 1e3; }));
  CHECK(refused([](dsmc::Config& k) { k.thermostat = dsmc::Thermostat::isokinetic; }));
  CHECK(refused([](dsmc::Config& k) { k.shear_rate = 1, k.scheme = dsmc::Scheme::lanes; }));
  CHECK(refused([](dsmc::Config& k) {
    k.shear_rate = 1, k.restitution = 0.9, k.thermostat = dsmc::Thermostat::isokinetic;
  }));
  dsmc::Config one = c;
  one.shear_rate = 1.0;
  one.init = InitialState::delta;
  one.initial.mass_ratio = 3.0;
  one.initial.fraction = 0.5;
  CHECK_THROWS_AS((dsmc::Engine<1, dsmc::HardSpheres, Features{.species = true}>(one)),
                  InvalidInput);
}

TEST_CASE("Hard spheres in shear flow: the a -> 0 viscosity is Pekeris-Alterman's",
          "[dsmc][shear][long]") {
  // eta(a) = -P_xy / (p a) of 3D hard spheres under the isokinetic thermostat at a = 0.06
  // and 0.12 (per mean collision time), N = 1e5, samples every 0.5 over [20, 1500]; eta(a)
  // = eta0 (1 - c2 a^2 + c4 a^4 ...), so (4 eta(0.06) - eta(0.12)) / 3 = eta0 (1 - 5.2e-5
  // c4): with the Maxwell-molecule c4 scaled to hard spheres (about 9), 5e-4 of eta0. The
  // converged Chapman-Enskog value is 1.016034 x the first Sonine 5/4 (Pekeris and Alterman,
  // Proc. Natl. Acad. Sci. USA 43, 998 (1957)); the finite-N correction is O(1/N) = 1e-5.
  // The two runs are cut into 20 blocks each; block k of both gives one extrapolated
  // value; within 4 standard errors of the 20 (t with 19 dof: P(|t| > 4) = 7.7e-4).
  constexpr int blocks = 20;
  std::vector<std::vector<double>> eta;
  for (double a : {0.06, 0.12}) {
    dsmc::Config c;
    c.n = 100000;
    c.init = InitialState::maxwell;
    c.seed = 31;
    c.shear_rate = a;
    c.thermostat = dsmc::Thermostat::isokinetic;
    dsmc::Engine<3, dsmc::HardSpheres> e(c);
    Tensor t;
    t.from = 20.0;
    e.run_until(1500.0, &t, 0.5);
    std::vector<double> y;
    for (double x : t.xy) y.push_back(-x / a / 1.25);
    eta.push_back(analysis::block_means(y, 0, y.size(), blocks));
  }
  std::vector<double> eta0;
  for (int k = 0; k < blocks; ++k) eta0.push_back((4.0 * eta[0][k] - eta[1][k]) / 3.0);
  const analysis::MeanSe m = analysis::mean_se(eta0);
  const analysis::MeanSe m1 = analysis::mean_se(eta[0]), m2 = analysis::mean_se(eta[1]);
  INFO("eta/eta_Sonine: a = 0.06 " << m1.mean << " +- " << m1.se << ", a = 0.12 " << m2.mean
                                   << " +- " << m2.se << "; a -> 0 " << m.mean << " +- " << m.se);
  CHECK(std::abs(m.mean - 1.016034) <= 4.0 * m.se);
  CHECK(4.0 * m.se <= 0.012);  // measured: 4 se = 0.0077
}
