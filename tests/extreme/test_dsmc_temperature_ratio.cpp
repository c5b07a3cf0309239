// Temperature ratio 1e6 in DSMC: two particles at 1e6 times the temperature of the others.
//
// The global majorant of dsmc::Engine (G = 2 max|v|) then rejects almost every candidate;
// dsmc::ClassEngine (per-particle speed-class bounds, dsmc/speed_classes.hpp) simulates the
// same exact Kac process at an acceptance that does not depend on the spread of speeds.
// Checked: (1) the class engine reproduces the exact engine (same law of the process) in
// ordinary relaxations; (2) in the stiff case both engines stay finite and conserve energy
// and momentum to round-off, their kurtosis agrees during the hot cascade (t = 0.05, 0.5)
// and the gas ends Maxwellian at the mixed temperature: <|v|^4> / <|v|^2>^2 = (D + 2)/D
// (Maxwell-Boltzmann in D dims, <v^4> = D (D+2) (kT/m)^2); (3) the class engine's
// acceptance in the stiff phase is > 100 times the global majorant's (a property of the
// algorithm, ~1e-3 versus ~0.4; the wall-clock comparison is in bench/bench_stiff.cpp).
// Statistical comparisons: Welch / Student t tests at false-failure probability 1e-4 each
// (15 comparisons: 1.5e-3 in all).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "extreme/extreme_common.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/dsmc/speed_classes.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;

namespace {

/// <|v|^4> / <|v|^2>^2 of a particle set (squares formed after normalising by <|v|^2>).
template <int D, Features F>
double kurtosis(const Particles<D, F>& p) {
  double m2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) m2 += p.velocity(i).squaredNorm();
  m2 /= p.size();
  double m4 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.velocity(i).squaredNorm() / m2;
    m4 += x * x;
  }
  return m4 / p.size();
}

/// Welch comparison of two replica samples at false-failure probability 1e-4.
void require_same(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
  const auto [ma, sa] = extreme::mean_se(a);
  const auto [mb, sb] = extreme::mean_se(b);
  INFO(what << ": " << ma << " +- " << sa << " vs " << mb << " +- " << sb);
  REQUIRE(std::abs(ma - mb) < extreme::t_threshold(1e-4, static_cast<int>(a.size())) *
                                  std::sqrt(sa * sa + sb * sb));
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("DSMC speed classes reproduce the exact engine", "[dsmc][extreme]",
                       ((int D), D), 2, 5) {
  // Hard spheres from the delta shell, kurtosis at t = 1 (mid-relaxation), N = 1e4,
  // R = 8 replicas per engine; and VHS (a = 0.5) in the same way.
  const int R = 8;
  auto compare = [&](auto model) {
    using M = decltype(model);
    std::vector<double> ke(R), kc(R);
    extreme::for_replicas(R, [&](int r) {
      Config cfg;
      cfg.n = 10000;
      cfg.model = M::kind;
      cfg.init = InitialState::delta;
      cfg.seed = 300 + r;
      Engine<D, M> e(cfg);
      e.run_until(1.0);
      ke[r] = kurtosis(e.particles());
      cfg.seed = 700 + r;
      ClassEngine<D, M> c(cfg);
      c.run_until(1.0);
      kc[r] = kurtosis(c.particles());
    });
    require_same(kc, ke, "kurtosis at t = 1, classes vs global majorant");
  };
  compare(HardSpheres{});
  compare(VariableHardSpheres{});
}

TEMPLATE_TEST_CASE_SIG("DSMC temperature ratio 1e6: stiff majorant, speed classes",
                       "[dsmc][extreme]", ((int D), D), 2, 3, 6) {
  const int R = 8;
  const std::size_t N = 20000;
  const std::vector<double> times = {0.05, 0.5, 20.0};
  Config cfg;
  cfg.n = N;
  cfg.init = InitialState::two_temp;
  cfg.initial.fraction = 2.0 / N;  // the last two particles are hot
  cfg.initial.kT_species = {1.0, 1e6};
  std::vector<std::vector<double>> ke(times.size(), std::vector<double>(R)), kc = ke;
  std::vector<double> acc_e(R), acc_c(R);
  std::vector<int> ok(R, 0);
  extreme::for_replicas(R, [&](int r) {
    Config c = cfg;
    c.seed = 5000 + 17 * D + r;
    Engine<D, HardSpheres> e(c);
    c.seed += 100000;
    ClassEngine<D, HardSpheres> s(c);
    const auto c0e = conserved(e.particles()), c0s = conserved(s.particles());
    for (std::size_t k = 0; k < times.size(); ++k) {
      e.run_until(times[k]);
      s.run_until(times[k]);
      ke[k][r] = kurtosis(e.particles());
      kc[k][r] = kurtosis(s.particles());
      if (k == 0) {
        acc_e[r] = static_cast<double>(e.collisions()) / static_cast<double>(e.candidates());
        acc_c[r] = s.acceptance();
      }
    }
    const auto [de, dpe] = extreme::drifts<D>(c0e, conserved(e.particles()));
    const auto [ds, dps] = extreme::drifts<D>(c0s, conserved(s.particles()));
    ok[r] = extreme::all_finite(e.particles()) && extreme::all_finite(s.particles()) &&
            de < 1e-12 && dpe < 1e-12 && ds < 1e-12 && dps < 1e-12;
  });
  for (int r = 0; r < R; ++r) REQUIRE(ok[r]);
  require_same(kc[0], ke[0], "kurtosis at t = 0.05");
  require_same(kc[1], ke[1], "kurtosis at t = 0.5");
  // Maxwellian at the end: both engines pooled (16 replicas) against (D + 2)/D.
  std::vector<double> all = ke[2];
  all.insert(all.end(), kc[2].begin(), kc[2].end());
  const auto [m, se] = extreme::mean_se(all);
  INFO("D = " << D << ": final kurtosis " << m << " +- " << se << ", Maxwell " << (D + 2.0) / D);
  REQUIRE(std::abs(m - (D + 2.0) / D) < extreme::t_threshold(1e-4, 2 * R) * se);
  REQUIRE(se < 0.01);
  const auto [ae, sae] = extreme::mean_se(acc_e);
  const auto [ac, sac] = extreme::mean_se(acc_c);
  WARN("D = " << D << ": acceptance in the stiff phase (t < 0.05): global majorant " << ae
              << ", speed classes " << ac);
  REQUIRE(ac > 100.0 * ae);
}

TEST_CASE("DSMC speed classes: N = 2, tiny and huge velocity scales", "[dsmc][extreme]") {
  // N = 2 keeps both speeds (zero momentum); scales 1e-150 and 1e150 give the same
  // acceptance statistics and conserve energy to round-off.
  for (double s : {1e-150, 1.0, 1e150}) {
    Config cfg;
    cfg.n = 2;
    cfg.initial.kT = s * s;
    ClassEngine<4, HardSpheres> e(cfg);
    const double v0 = e.particles().velocity(0).norm();
    e.run_until(1000.0);
    REQUIRE(e.collisions() > 100);
    REQUIRE(std::abs(e.particles().velocity(0).norm() - v0) < 1e-12 * v0);
    cfg.n = 5000;
    ClassEngine<6, HardSpheres> f(cfg);
    const auto c0 = conserved(f.particles());
    f.run_until(2.0);
    const auto [de, dp] = extreme::drifts<6>(c0, conserved(f.particles()));
    REQUIRE(extreme::all_finite(f.particles()));
    REQUIRE(de < 1e-12);
    REQUIRE(dp < 1e-12);
    REQUIRE(f.acceptance() > 0.2);
  }
}
