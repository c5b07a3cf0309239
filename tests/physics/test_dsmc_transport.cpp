// Green-Kubo transport coefficients of the Boltzmann gas (analysis/transport_recorder.hpp,
// docs/validation.md, "Transport coefficients").
//
// Maxwell molecules (isotropic scattering, every pair at the same rate): in the N-particle
// process at zero momentum the conditional mean of each flux decays exactly exponentially,
//   stress        gamma = (1/2) N / (N - 1),
//   heat flux     gamma = (D - 1) / (2 D) N / (N - 1),
//   tagged vel.   gamma = (1/2) N / (N - 1),
// so each correlation is C(0) exp(-gamma t) and its integral C(0) / gamma. Measured rates
// and integrals are compared with these at 4 standard errors (false failure 6e-5 per
// comparison, 3 coefficients x 2 quantities x 5 dimensions: below 2e-3 for the case). The
// standard errors come from 32 stretches of the run (Student t with 31 degrees of freedom:
// 4 se is a two-sided 3e-4, so the case's false-failure probability is below 1e-2).
//
// Green-Kubo and Einstein forms of self-diffusion (exact virtual displacements) agree in
// every D: paired per stretch, 4 se (false failure 3e-4 each, Student t with 31 dof).
//
// Hard spheres, 3D (long): eta / eta_0 = 1.016034 and lambda / lambda_0 = 1.025218
// (Pekeris & Alterman, Proc. Natl. Acad. Sci. USA 43, 998 (1957)) within 0.5 % and 3 se;
// D_s / D_0 in [1.00, 1.04] (the Chapman-Cowling higher Sonine corrections of hard-sphere
// self-diffusion are about 1.02). The N-particle process differs from the Boltzmann gas at
// O(1/N), and for hard spheres measurably so (measured I = I_inf (1 - a/N) with a about 2.3
// for eta, 4.7 for lambda, 1.7 for D_s: -0.5 % for lambda at N = 1000; for Maxwell
// molecules the stress's a is exactly (2D + 2)/D). So the case runs N = 1000 twice and
// N = 250 once, for 2.4e6 mean collision times each (about 4 minutes on two cores), and
// extrapolates linearly in 1/N: I_inf = (1000 I_1000 - 250 I_250) / 750, its standard error
// from the runs' (about 0.12 % for eta and 0.2 % for lambda; the O(1/N^2) remainder is
// below 1e-4). The 0.5 % bound then fails by chance with probability below 1e-4 (eta) and
// about 1.2 % (lambda), for the case about 1 %; its seeds are fixed.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "hypergas/analysis/transport_recorder.hpp"
#include "hypergas/dsmc/engine.hpp"

using namespace hypergas;

namespace {

template <int D, class Model>
std::vector<analysis::TransportCoefficient> measure(std::size_t n, double until,
                                                    const analysis::TransportSettings& ts,
                                                    std::uint64_t seed) {
  dsmc::Config cfg;
  cfg.n = n;
  cfg.seed = seed;
  cfg.init = InitialState::maxwell;
  dsmc::Engine<D, Model> e(cfg);
  // the samples (the recorder's error stretches are cut from this count); run_until takes
  // at most 1e6 samples a call, so the run goes in stretches of 1000
  const auto frames = static_cast<std::uint64_t>(std::llround((until - ts.warmup) / ts.dt)) + 1;
  // the model's collision law, from its type
  analysis::TransportRecorder rec(ts, D, n, frames,
                                  {Model{}.exponent(), Model::isotropic_scattering});
  for (double t = 0.0; t < until;) {
    t = std::min(until, t + 1000.0);
    e.run_until(t, &rec, ts.dt);
  }
  REQUIRE(rec.frames() == frames);
  return rec.finish();
}

/// Green-Kubo and Einstein self-diffusion from the same run agree: the difference of the
/// two per error stretch has mean zero (4 se of the paired differences).
void check_einstein(const std::vector<analysis::TransportCoefficient>& r, int D) {
  const auto& gk = r[2];
  const auto& e = r[3];
  REQUIRE(e.name == "self_diffusion_einstein");
  REQUIRE(gk.stretches.size() == e.stretches.size());
  const std::size_t J = gk.stretches.size();
  double m = 0.0, m2 = 0.0;
  for (std::size_t j = 0; j < J; ++j) {
    const double d = e.stretches[j] - gk.stretches[j];
    m += d, m2 += d * d;
  }
  m /= double(J);
  const double se = std::sqrt((m2 / double(J) - m * m) / double(J - 1));
  INFO("D = " << D << ": Green-Kubo " << gk.value << " +- " << gk.error << ", Einstein "
              << e.value << " +- " << e.error << ", paired difference " << m << " +- " << se);
  CHECK(std::abs(e.value - gk.value) < 4.0 * se + 1e-12);
}

template <int D>
void check_maxwell() {
  const std::size_t N = 1000;
  analysis::TransportSettings ts;
  ts.dt = 0.05;
  ts.max_lag = 30.0;
  ts.tagged = 16;
  ts.warmup = 5.0;  // the Maxwellian start is the equilibrium already
  const auto r = measure<D, dsmc::MaxwellMolecules>(N, 20000.0, ts, 70 + D);
  const double f = N / (N - 1.0);
  const double exact[3] = {0.5 * f, (D - 1.0) / (2.0 * D) * f, 0.5 * f};
  for (int g = 0; g < 3; ++g) {
    const auto& c = r[std::size_t(g)];
    INFO("D = " << D << ", " << c.name << ": rate " << c.rate << " +- " << c.rate_error
                << " (exact " << exact[g] << "), integral " << c.value << " +- " << c.error
                << " (C(0)/rate " << c.c0 / exact[g] << ")");
    CHECK(std::abs(c.rate - exact[g]) < 4.0 * c.rate_error);
    CHECK(std::abs(c.value - c.c0 / exact[g]) < 4.0 * c.error);
    // the first Sonine value is exact for Maxwell molecules, up to the 1/N terms
    CHECK(std::abs(c.ratio - 1.0) < 4.0 * c.ratio_error + 5.0 / N);
  }
  check_einstein(r, D);
}

}  // namespace

TEST_CASE("Transport, Maxwell molecules: exact decay rates and integrals in D = 2..6",
          "[transport][physics]") {
  check_maxwell<2>();
  check_maxwell<3>();
  check_maxwell<4>();
  check_maxwell<5>();
  check_maxwell<6>();
}

TEST_CASE("Transport, hard spheres 3D: Pekeris-Alterman viscosity and conductivity",
          "[transport][physics][long]") {
  // two gas sizes side by side (two threads), extrapolated linearly in 1/N
  analysis::TransportSettings ts;
  ts.dt = 0.1;
  ts.max_lag = 20.0;
  ts.tagged = 8;
  ts.warmup = 5.0;
  const double until = 2.4e6, n1 = 250, n2 = 1000;
  // two runs of N = 1000 (one per thread), then one of N = 250
  std::vector<analysis::TransportCoefficient> r1, r2, r3;
  std::thread other([&] {
    r3 = measure<3, dsmc::HardSpheres>(1000, until, ts, 2027);
    r1 = measure<3, dsmc::HardSpheres>(250, until, ts, 2025);
  });
  r2 = measure<3, dsmc::HardSpheres>(1000, until, ts, 2026);
  other.join();
  for (std::size_t g = 0; g < 3; ++g) {  // the mean of the two N = 1000 runs
    r2[g].ratio = 0.5 * (r2[g].ratio + r3[g].ratio);
    r2[g].ratio_error = 0.5 * std::hypot(r2[g].ratio_error, r3[g].ratio_error);
  }
  const double exact[3] = {1.016034, 1.025218, 0.0};
  for (int g = 0; g < 3; ++g) {
    const auto& a = r1[std::size_t(g)];
    const auto& b = r2[std::size_t(g)];
    const double inf = (n2 * b.ratio - n1 * a.ratio) / (n2 - n1);
    const double se = std::hypot(n2 * b.ratio_error, n1 * a.ratio_error) / (n2 - n1);
    const double slope = (b.ratio - a.ratio) / (1.0 / n1 - 1.0 / n2) / inf;  // I = I_inf (1 - a/N)
    INFO(a.name << ": N = 250 " << a.ratio << " +- " << a.ratio_error << ", N = 1000 " << b.ratio
                << " +- " << b.ratio_error << "; N -> inf " << inf << " +- " << se
                << " (1/N coefficient " << slope << ")");
    if (g < 2) {
      CHECK(se < 0.0022);
      CHECK(std::abs(inf - exact[g]) < 0.005);
      CHECK(std::abs(inf - exact[g]) < 3.0 * se);
    } else {
      CHECK(inf > 1.0);
      CHECK(inf < 1.04);
    }
  }
  check_einstein(r2, 3);
}

TEMPLATE_TEST_CASE_SIG("Transport, hard spheres: Green-Kubo and Einstein self-diffusion agree",
                       "[transport][physics]", ((int D), D), 2, 4, 5, 6) {
  analysis::TransportSettings ts;
  ts.max_lag = 20.0;
  ts.tagged = 32;
  ts.warmup = 5.0;
  check_einstein(measure<D, dsmc::HardSpheres>(500, 4000.0, ts, 90 + D), D);
}
