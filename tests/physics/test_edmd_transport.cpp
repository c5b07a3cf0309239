// Transport coefficients of the EDMD hard-sphere fluid (analysis/helfand_recorder.hpp;
// docs/validation.md, "Transport of the hard-sphere fluid").
//
// Forms that must agree. From one run: the Einstein-Helfand slope of the mean square
// Helfand moment and the Green-Kubo integral of the interval fluxes (viscosity and thermal
// conductivity); the kinetic part from the event-by-event time integral of the kinetic
// stress and from its point samples; Green-Kubo and Einstein self-diffusion. Each pair is
// compared through its difference per error stretch (32 stretches: the difference's mean
// over its standard error is Student t with 31 dof), at 5 se: a two-sided 2e-5 each, 2e-4
// for the case's ten comparisons. Both estimators are read at one cut with one tail
// (the plateau rule, analysis/src/integrals.hpp): the slope is fitted over [k_c/2, 3k_c/2]
// around it, the sum ends at it.
//
// Two engines, one gas (long). At low density (Z - 1 = 2^(D-1) eta g(sigma+) about 0.04:
// eta = 0.04 / 2^(D-1), D = 2..6) the EDMD coefficients over their Enskog values (first
// Sonine, g(sigma+) from the measured collision rate; analysis/enskog.hpp) equal the
// velocity-space engine's Boltzmann values over the first Sonine ones, at the same N (the
// N-particle corrections of both engines are then the same to O(n)). Compared: viscosity
// and thermal conductivity (Green-Kubo) and self-diffusion (Einstein), each within 4.5
// combined se (t with 31 dof: two-sided 2e-4 each, 3e-3 for the 15 comparisons; the EDMD
// error includes its truncation error, a bound, which only lowers that probability). Density
// corrections beyond Enskog at Z - 1 = 0.04 are below 0.5 % (Alder, Gass & Wainwright,
// J. Chem. Phys. 53, 3813 (1970): eta / eta_E and D / D_E within a few per cent of 1 up to
// V / V_0 = 3), well inside the 3 % errors of the comparison.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hypergas/analysis/enskog.hpp"
#include "hypergas/analysis/helfand_recorder.hpp"
#include "hypergas/analysis/transport_recorder.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/edmd/engine.hpp"

using namespace hypergas;
using analysis::TransportCoefficient;

namespace {

const TransportCoefficient& row(const std::vector<TransportCoefficient>& r, const std::string& n) {
  for (const auto& c : r)
    if (c.name == n) return c;
  FAIL("no row " << n);
  return r.front();
}

/// EDMD: equilibrate for t_eq, record to `until` (snapshots every (until - t_eq) / 2000).
template <int D>
std::vector<TransportCoefficient> md(std::size_t n, double eta, double t_eq, double until,
                                     const analysis::TransportSettings& ts, std::uint64_t seed) {
  edmd::Config cfg;
  cfg.n = n;
  cfg.packing = eta;
  cfg.seed = seed;
  edmd::Engine<D> e(cfg);
  e.run_until(t_eq);
  analysis::HelfandRecorder rec(ts, D, n, t_eq, until);
  e.run_until(until, &rec, (until - t_eq) / 2000.0);
  return rec.finish();
}

/// Paired difference of rows a and b per error stretch: |mean| <= k se.
void check_paired(const std::vector<TransportCoefficient>& r, const std::string& a,
                  const std::string& b, double k) {
  const auto& x = row(r, a);
  const auto& y = row(r, b);
  std::vector<double> d;
  for (std::size_t j = 0; j < x.stretches.size(); ++j) d.push_back(x.stretches[j] - y.stretches[j]);
  double m = 0, s2 = 0;
  for (double v : d) m += v;
  m /= double(d.size());
  for (double v : d) s2 += (v - m) * (v - m);
  const double se = std::sqrt(s2 / double(d.size() - 1) / double(d.size()));
  INFO(a << " = " << x.value << " +- " << x.error << ", " << b << " = " << y.value << " +- "
         << y.error << ": difference " << x.value - y.value << " (per stretch " << m << " +- "
         << se << ")");
  CHECK(std::fabs(x.value - y.value) <= k * se);
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("EDMD transport: Einstein-Helfand and Green-Kubo forms agree",
                       "[edmd][physics][transport]", ((int D), D), 2, 3) {
  analysis::TransportSettings ts;
  ts.max_lag = 20.0;
  const double eta = D == 2 ? 0.3 : 0.2;
  const auto r = md<D>(500, eta, 10.0, D == 2 ? 6000.0 : 3200.0, ts, 3);
  for (const char* base : {"viscosity", "thermal_conductivity"}) {
    check_paired(r, base, std::string(base) + "_green_kubo", 5.0);
    check_paired(r, std::string(base) + "_kinetic", std::string(base) + "_kinetic_point", 5.0);
  }
  check_paired(r, "self_diffusion", "self_diffusion_einstein", 5.0);
  // the parts add up, and the collisional parts are positive at this density
  for (const char* base : {"viscosity", "thermal_conductivity"}) {
    const std::string b = base;
    CHECK(row(r, b + "_kinetic").value + row(r, b + "_cross").value +
              row(r, b + "_collisional").value ==
          Approx(row(r, b + "_green_kubo").value).epsilon(1e-12));
    CHECK(row(r, b + "_collisional").value > 5.0 * row(r, b + "_collisional").error);
  }
}

namespace {

template <int D>
std::vector<TransportCoefficient> boltzmann(std::size_t n, double until, std::uint64_t seed) {
  analysis::TransportSettings ts;
  ts.max_lag = 20.0;
  dsmc::Config cfg;
  cfg.n = n;
  cfg.seed = seed;
  cfg.init = InitialState::maxwell;
  dsmc::Engine<D, dsmc::HardSpheres> e(cfg);
  const auto frames = static_cast<std::uint64_t>(std::llround((until - ts.warmup) / ts.dt)) + 1;
  using HS = dsmc::HardSpheres;  // the hard-sphere collision law, from the model type
  analysis::TransportRecorder rec(ts, D, n, frames, {HS::exponent(), HS::isotropic_scattering});
  for (double t = 0.0; t < until;) {
    t = std::min(until, t + 1000.0);
    e.run_until(t, &rec, ts.dt);
  }
  return rec.finish();
}

template <int D>
void two_engines(std::size_t n, double mean_free_times) {
  const double eta = 0.04 / std::pow(2.0, D - 1);
  const double density = eta / analysis::enskog::sphere_volume(D);
  const double tau = 1.0 / analysis::enskog::boltzmann_rate(D, density);  // about
  analysis::TransportSettings ts;
  ts.dt = 0.1;
  ts.max_lag = 20.0;
  const auto m = md<D>(n, eta, 50.0 * tau, (50.0 + mean_free_times) * tau, ts, 7);
  const auto b = boltzmann<D>(n, 2.0 * mean_free_times, 8);
  const std::pair<const char*, const char*> pairs[] = {
      {"viscosity_green_kubo", "viscosity"},
      {"thermal_conductivity_green_kubo", "thermal_conductivity"},
      {"self_diffusion_einstein", "self_diffusion_einstein"}};
  for (const auto& [mn, bn] : pairs) {
    const auto& x = row(m, mn);
    const auto& y = row(b, bn);
    const double se = std::hypot(x.enskog_ratio_error, y.ratio_error);
    INFO("D = " << D << ", eta = " << eta << ": EDMD " << mn << " / Enskog = " << x.enskog_ratio
                << " +- " << x.enskog_ratio_error << ", DSMC " << bn << " / first Sonine = "
                << y.ratio << " +- " << y.ratio_error);
    CHECK(std::fabs(x.enskog_ratio - y.ratio) <= 4.5 * se);
    // the comparison has power: the EDMD error includes the plateau rule's truncation
    // error (integrals.hpp), which for these exponential decays is the remainder of the
    // slowest (t^(-D/2)) tail allowed, 0.03-0.06 of the value at this run length
    CHECK(x.enskog_ratio_error < 0.08);
  }
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("two engines, one gas: dilute EDMD over Enskog equals DSMC's Boltzmann "
                       "values", "[edmd][physics][transport][long]", ((int D), D), 2, 3, 4, 5, 6) {
  two_engines<D>(D == 6 ? 250 : 500, D >= 5 ? 10000.0 : 20000.0);
}
