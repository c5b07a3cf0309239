// Example 08 -- viscosity, heat conduction and self-diffusion of the Boltzmann gas in
// D = 2..6, from equilibrium fluctuations.
//
// The story. Chapman and Enskog turned the Boltzmann equation into transport coefficients;
// their first Sonine approximation gives closed forms in every dimension (docs/validation.md
// derives them for hard spheres: eta* = (D+2)/4, lambda* = D (D+2)^2 / (8 (D-1)),
// D* = D/2, reduced by n kT tau, n k_B (kT/m) tau and (kT/m) tau with tau the mean
// collision time). The exact values lie a little above: in 3D the converged Sonine series
// gives eta/eta_0 = 1.016034 and lambda/lambda_0 = 1.025218 (Pekeris & Alterman 1957).
// What are the corrections in other dimensions?
//
// Green and Kubo answer without a flow or a gradient: a coefficient is the time integral of
// an equilibrium correlation of a collective flux. The velocity-space engine keeps the
// kinetic stress sum_i v_x v_y and the heat flux sum_i v_x (v^2/2 - (D+2) kT/2) exactly,
// collision by collision (tally/fluxes.hpp); analysis::TransportRecorder correlates them
// (and the velocities of tagged particles) on a fine grid and integrates. The relative
// error of a collective correlation does not shrink with N (both the flux and its
// fluctuation grow as sqrt(N)), so a small gas run for a long time is the cheap way:
// N = 1000 here, where the 1/N corrections are ~0.2 %.
//
// Usage: example_08 [--short]   (writes transport_D<d>.csv in the current folder)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "hypergas/analysis/transport_recorder.hpp"
#include "hypergas/dsmc/engine.hpp"

using namespace hypergas;

template <int D>
std::vector<analysis::TransportCoefficient> measure(double until, std::uint64_t seed) {
  dsmc::Config cfg;
  cfg.n = 1000;
  cfg.seed = seed;
  cfg.init = InitialState::maxwell;  // the equilibrium: no relaxation to wait for
  dsmc::Engine<D, dsmc::HardSpheres> gas(cfg);
  analysis::TransportSettings ts;  // dt 0.05, lags to 40, window of 3 integral times
  ts.tagged = 16;
  ts.warmup = 5.0;
  // samples from t = warmup on (the error stretches are cut from this count); run_until
  // takes at most 1e6 samples a call, so the run goes in stretches of 1000
  const auto frames = static_cast<std::uint64_t>(std::llround((until - ts.warmup) / ts.dt)) + 1;
  using HS = dsmc::HardSpheres;  // the hard-sphere collision law, from the model type
  analysis::TransportRecorder rec(ts, D, cfg.n, frames, {HS::exponent(), HS::isotropic_scattering});
  for (double t = 0.0; t < until;) {
    t = std::min(until, t + 1000.0);
    gas.run_until(t, &rec, ts.dt);
  }
  const auto r = rec.finish();
  rec.write_transport_csv("transport_D" + std::to_string(D) + ".csv");
  return r;
}

int main(int argc, char** argv) {
  const bool short_run = argc > 1 && std::strcmp(argv[1], "--short") == 0;
  const double until = short_run ? 2000.0 : 200000.0;
  fmt::print("hard spheres, N = 1000, {} mean collision times per D; reduced coefficients\n",
             until);
  fmt::print("{:>2}  {:>22}  {:>22}  {:>22}  {:>22}  {:>6}\n", "D", "eta / eta_0",
             "lambda / lambda_0", "D_s / D_0 (Green-Kubo)", "D_s / D_0 (Einstein)", "s");
  bool ok = true;
  auto t0 = std::chrono::steady_clock::now();
  const auto row = [&](int d, const std::vector<analysis::TransportCoefficient>& r) {
    const auto t1 = std::chrono::steady_clock::now();
    fmt::print("{:>2}", d);
    for (const auto& c : r)
      fmt::print("  {:>8.4f} +- {:.4f} ({:4.2f})", c.ratio, c.ratio_error, c.sonine);
    fmt::print("  {:>6.1f}\n", std::chrono::duration<double>(t1 - t0).count());
    t0 = t1;
    // what you should see: every ratio within a few per cent above 1 (the first Sonine
    // approximation is a lower bound of the viscosity and conductivity of hard spheres,
    // a variational result), and within 6 se of 1..1.06 (a check, false failure ~1e-8)
    for (const auto& c : r)
      ok = ok && c.ratio > 1.0 - 6.0 * c.ratio_error && c.ratio < 1.06 + 6.0 * c.ratio_error;
  };
  row(2, measure<2>(until, 82));
  row(3, measure<3>(until, 83));
  row(4, measure<4>(until, 84));
  row(5, measure<5>(until, 85));
  row(6, measure<6>(until, 86));
  fmt::print("(in parentheses: the first Sonine value, reduced)\n");
  fmt::print("{}\n", ok ? "as expected" : "UNEXPECTED: see transport_D*.csv");
  return ok ? 0 : 1;
}
