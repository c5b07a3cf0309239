// The exact Kac process and Bird's NTC scheme agree as the NTC step goes to zero, and the
// NTC step error falls as the step falls. 3D hard spheres from the delta shell (every speed
// sqrt(3)), where a step error shows most: the relaxation creates speeds far above the
// initial maximum, and NTC freezes the bound G on relative speeds for a whole step, so
// pairs faster than G are under-sampled (accepted with probability 1 instead of |g|/G > 1)
// until the step ends (dsmc/engine.hpp). Every seed is fixed; replicas have consecutive
// seeds, a separate range per scheme and step, so the samples are independent.
//
// 1. Agreement at dt = 0.01: the fourth moment m4 at t = 1 and t = 3 (R = 16 replicas of
//    N = 20 000 per scheme) and the collisions per particle at t = 1 (the samples of 2.):
//    the difference of replica means over its standard error (Welch) must lie within the
//    two-sided Student-t bound at false-failure probability 1e-5 per comparison (3
//    comparisons: 3e-5 in all).
// 2. The error falls: observable c(dt) = mean collisions per particle at t = 1 (R = 64 NTC
//    replicas of N = 200 000 per step, Rx = 128 exact replicas); error e(dt) = c_ntc(dt) -
//    c_exact. The under-sampling only removes collisions, so e < 0: measured e(1) = -0.4 to
//    -0.5 % and e(0.5) = -0.07 to -0.12 % of c_exact = 1.021. The test requires
//    (a) e(1) < 0, (b) e(0.5) - e(1) > 0 and (c) -e(1) - e(0.5) > 0, each by more than
//    zc = 3 standard errors of its own statistic (replica means independent, so the
//    variances add; the exact mean enters (c) twice). (b) and (c) together are |e(0.5)| <
//    |e(1)|. Tolerance from the sample size: the standard errors are the replicas' spread
//    over sqrt(R) (relative standard error of c_exact 2.7e-4 at Rx = 128, N = 200 000);
//    at these R and N, calibration runs on four other seed ranges gave z (a) -13.2..-15.0,
//    (b) 10.7..11.5, (c) 8.0..10.1 (the fixed seeds here: -11.0, 8.8, 7.1). With
//    z ~ N(expected, 1), even the lowest calibrated values give a false-failure probability
//    below Phi(3 - 8.0) + Phi(3 - 10.7) + Phi(3 - 13.2) = 3e-7 (< 1e-5 as the project
//    requires); a scheme whose error did not fall (e(0.5) = e(1)) passes (b) with
//    probability Phi(-3) = 1.3e-3.
// The step errors are printed (WARN).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hypergas/dsmc/engine.hpp"
#include "physics/test_dsmc_common.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;
using namespace dsmc_test;

namespace {
constexpr int R = 16;
std::vector<std::vector<double>> m4_runs(Scheme s, double dt, std::uint64_t seed0) {
  std::vector<std::vector<double>> out(2, std::vector<double>(R));
  for_replicas(R, [&](int r) {
    Config cfg;
    cfg.n = 20000;
    cfg.init = InitialState::delta;
    cfg.scheme = s;
    cfg.dt = dt;
    cfg.seed = seed0 + r;
    Engine<3, HardSpheres> e(cfg);
    e.run_until(1.0);
    out[0][r] = moment(e.particles(), 2);
    e.run_until(3.0);
    out[1][r] = moment(e.particles(), 2);
  });
  return out;
}

/// Collisions per particle at t = 1 of `replicas` runs of N = 200 000 (seeds seed0 + r).
std::vector<double> collision_runs(Scheme s, double dt, std::uint64_t seed0, int replicas) {
  std::vector<double> out(replicas);
  for_replicas(replicas, [&](int r) {
    Config cfg;
    cfg.n = 200000;
    cfg.init = InitialState::delta;
    cfg.scheme = s;
    cfg.dt = dt;
    cfg.seed = seed0 + r;
    Engine<3, HardSpheres> e(cfg);
    e.run_until(1.0);
    out[r] = e.collisions_per_particle();
  });
  return out;
}

struct Sample {
  double mean, se;
};
Sample stats(const std::vector<double>& x) {
  const auto [m, s] = mean_se(x);
  return {m, s};
}

constexpr double zc = 3.0;      // one-sided bound of the step-error comparisons (2.)
constexpr int R_ntc = 64, R_exact = 128;

const Sample& exact_collisions() {
  static const Sample s = stats(collision_runs(Scheme::exact, 1.0, 5000, R_exact));
  return s;
}
}  // namespace

TEST_CASE("NTC converges to the exact process as dt -> 0", "[dsmc][physics]") {
  const auto exact = m4_runs(Scheme::exact, 1.0, 100);
  const auto ntc = m4_runs(Scheme::ntc, 0.01, 210);
  for (int k = 0; k < 2; ++k) {
    const auto [me, se] = mean_se(exact[k]);
    const auto [mn, sn] = mean_se(ntc[k]);
    const double z = (mn - me) / std::sqrt(se * se + sn * sn);
    INFO("dt = 0.01, t = " << (k ? 3 : 1) << ": exact m4 " << me << " +- " << se << ", NTC "
                           << mn << " +- " << sn << ", z = " << z);
    CHECK(std::abs(z) < t_threshold(1e-5, 2 * R - 1));
  }
  // The collision count, the observable where the step error shows at dt = 0.5 and 1.
  const Sample x = exact_collisions();
  const Sample n = stats(collision_runs(Scheme::ntc, 0.01, 8000, R_ntc));
  const double z = (n.mean - x.mean) / std::hypot(n.se, x.se);
  INFO("dt = 0.01: collisions per particle at t = 1: exact " << x.mean << " +- " << x.se
                                                             << ", NTC " << n.mean << " +- "
                                                             << n.se << ", z = " << z);
  CHECK(std::abs(z) < t_threshold(1e-5, R_ntc + R_exact - 1));
}

TEST_CASE("NTC's step error falls as dt falls", "[dsmc][physics]") {
  const Sample x = exact_collisions();
  const Sample n1 = stats(collision_runs(Scheme::ntc, 1.0, 6000, R_ntc));
  const Sample nh = stats(collision_runs(Scheme::ntc, 0.5, 7000, R_ntc));
  const double e1 = n1.mean - x.mean, eh = nh.mean - x.mean;
  const double za = e1 / std::hypot(n1.se, x.se);
  const double zb = (eh - e1) / std::hypot(nh.se, n1.se);
  const double zo = -(e1 + eh) / std::sqrt(n1.se * n1.se + nh.se * nh.se + 4 * x.se * x.se);
  WARN("collisions per particle at t = 1: exact " << x.mean << " +- " << x.se << "; NTC error "
                                                  << "e(1) = " << e1 << " +- "
                                                  << std::hypot(n1.se, x.se) << ", e(0.5) = "
                                                  << eh << " +- " << std::hypot(nh.se, x.se));
  INFO("e(1) = " << e1 << ", e(0.5) = " << eh << "; z: (a) " << za << ", (b) " << zb
                 << ", (c) " << zo);
  CHECK(za < -zc);   // (a) the step error at dt = 1 is resolved, and a shortfall
  CHECK(zb > zc);    // (b) e(0.5) > e(1): it falls with dt ...
  CHECK(zo > zc);    // (c) ... and does not overshoot: |e(0.5)| < |e(1)|
}
