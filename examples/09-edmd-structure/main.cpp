// Example 09 -- the hard-sphere fluid's structure in 3D and 6D, and its viscosity against
// density next to Enskog's theory.
//
// The story. A hard-sphere fluid has no energy scale: its state is the packing fraction
// eta alone, and its pressure follows from one number of its structure, the contact value
// g(sigma+) of the radial distribution function: Z = PV/(NkT) = 1 + 2^(D-1) eta g(sigma+).
// At the same Z two dimensions therefore share the product 2^(D-1) eta g(sigma+), yet their
// structures differ: in 6D the fluid reaches Z = 4 at a packing many times lower than in
// 3D, and its g(r) is flatter beyond the first shell (in high dimensions the pair
// correlations beyond contact fade, the liquid approaches the mean-field limit).
//
// Part 1 finds the 6D packing with Z = 4 by a few secant steps on the measured Z, then
// records g(r) and S(k) of both fluids (analysis::StructureRecorder) and compares each
// contact value with the contact theorem.
//
// Part 2 measures the shear viscosity of the 3D fluid from dilute to dense by the
// Einstein-Helfand route (analysis::HelfandRecorder: the Helfand moment of the stress,
// kept event by event, kinetic and collisional parts) and sets it beside Enskog's theory
// with g(sigma+) from the measured collision rate. Enskog assumes uncorrelated collisions;
// the ratio measured/Enskog shows where correlated collision sequences (the molecular
// dynamics "ring" events) matter.
//
// Usage: example_09 [--short]  (writes rdf_3d.csv, rdf_6d.csv, structure_factor_3d.csv,
// structure_factor_6d.csv and viscosity_3d.csv in the current folder)
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "hypergas/analysis/enskog.hpp"
#include "hypergas/analysis/helfand_recorder.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/structure_recorder.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/edmd/observables.hpp"

using namespace hypergas;

/// Z of a D-dimensional fluid at packing eta (short run).
template <int D>
double measure_Z(double eta, std::size_t n, double t_eq, double t_run) {
  edmd::Config cfg;
  cfg.n = n;
  cfg.packing = eta;
  cfg.seed = 3;
  edmd::Engine<D> e(cfg);
  e.run_until(t_eq);
  e.reset_observables();
  e.run_until(t_eq + t_run);
  return e.pressure_Z();
}

/// g(r) and S(k) at packing eta; writes rdf_<D>d.csv and structure_factor_<D>d.csv.
template <int D>
analysis::StructureResult structure(double eta, std::size_t n, double until, double& Z) {
  edmd::Config cfg;
  cfg.n = n;
  cfg.packing = eta;
  cfg.seed = 5;
  edmd::Engine<D> e(cfg);
  const double t_eq = 0.2 * until;
  e.run_until(t_eq);
  e.reset_observables();
  analysis::StructureSettings ss;
  ss.r_max = 4.0;
  ss.k_max = 12.0;
  analysis::StructureRecorder rec(ss, D, n, t_eq);
  e.run_until(until, &rec, (until - t_eq) / 200.0);
  Z = e.pressure_Z();
  const auto& r = rec.finish();
  rec.write_rdf_csv(fmt::format("rdf_{}d.csv", D));
  rec.write_structure_factor_csv(fmt::format("structure_factor_{}d.csv", D));
  return r;
}

int main(int argc, char** argv) {
  const bool short_run = argc > 1 && std::strcmp(argv[1], "--short") == 0;
  const auto t0 = std::chrono::steady_clock::now();

  // ---- Part 1: 3D and 6D at Z = 4 ------------------------------------------------------
  const double Z_target = 4.0;
  const double eta3 = 0.3;  // Carnahan-Starling: Z(0.3) = 3.97
  // secant on ln(Z - 1) against eta in 6D, from two guesses
  double a = 0.03, b = 0.06;
  const std::size_t n6 = short_run ? 400 : 1000;
  const double t6 = short_run ? 2.0 : 8.0;
  double za = measure_Z<6>(a, n6, 1.0, t6), zb = measure_Z<6>(b, n6, 1.0, t6);
  for (int k = 0; k < 3; ++k) {
    const double c = b + (std::log(Z_target - 1.0) - std::log(zb - 1.0)) * (b - a) /
                             (std::log(zb - 1.0) - std::log(za - 1.0));
    a = b, za = zb, b = c, zb = measure_Z<6>(b, n6, 1.0, t6);
  }
  const double eta6 = b;
  double Z3 = 0, Z6 = 0;
  const auto s3 = structure<3>(eta3, short_run ? 500 : 2000, short_run ? 20.0 : 100.0, Z3);
  const auto s6 = structure<6>(eta6, short_run ? 400 : 2000, short_run ? 5.0 : 25.0, Z6);
  fmt::print("Part 1: the fluid at Z = PV/NkT = 4 in 3D and 6D\n");
  fmt::print("  D  packing   Z       g(sigma+) rdf     g(sigma+) from Z  S(k_min)\n");
  for (const auto& [d, eta, Z, s] : {std::tuple{3, eta3, Z3, &s3}, std::tuple{6, eta6, Z6, &s6}})
    fmt::print("  {}  {:.4f}    {:.3f}   {:.3f} +- {:.3f}   {:.3f}             {:.3f} (k = {:.2f})\n",
               d, eta, Z, s->contact, s->contact_error, edmd::contact_value(d, Z, eta), s->s[0],
               s->k[0]);

  // ---- Part 2: the 3D viscosity against density ------------------------------------------
  fmt::print("\nPart 2: 3D shear viscosity (Einstein-Helfand) over the dilute eta_0 and Enskog\n");
  fmt::print("  packing  chi     eta/eta_0          Enskog   measured/Enskog   collisional share\n");
  std::vector<std::vector<double>> rows;
  const std::vector<double> packings =
      short_run ? std::vector<double>{0.1, 0.3} : std::vector<double>{0.02, 0.1, 0.2, 0.3, 0.4, 0.45};
  const double mean_free_times = short_run ? 400.0 : 6000.0;
  for (const double eta : packings) {
    edmd::Config cfg;
    cfg.n = 500;
    cfg.packing = eta;
    cfg.seed = 9;
    edmd::Engine<3> e(cfg);
    // the mean free time from Enskog with Carnahan-Starling's contact value sets the length
    const double chi_cs = (1.0 - 0.5 * eta) / std::pow(1.0 - eta, 3);
    const double tau = 1.0 / (analysis::enskog::boltzmann_rate(3, eta / analysis::enskog::sphere_volume(3)) * chi_cs);
    const double t_eq = 50.0 * tau, until = t_eq + mean_free_times * tau;
    e.run_until(t_eq);
    analysis::TransportSettings ts;
    ts.max_lag = 30.0;
    analysis::HelfandRecorder rec(ts, 3, cfg.n, t_eq, until);
    e.run_until(until, &rec, (until - t_eq) / 1000.0);
    const auto& r = rec.finish();
    const auto& v = r[0];  // viscosity (Einstein-Helfand)
    double coll = 0.0;
    for (const auto& c : r)
      if (c.name == "viscosity_collisional") coll = c.value;
    const double eta0 = analysis::enskog::eta0(3);
    fmt::print("  {:.2f}     {:.3f}   {:7.3f} +- {:5.3f}  {:7.3f}  {:.3f} +- {:.3f}     {:.2f}\n", eta,
               rec.chi(), v.value / eta0, v.error / eta0, v.enskog / eta0, v.enskog_ratio,
               v.enskog_ratio_error, coll / v.value);
    rows.push_back({eta, rec.chi(), v.value / eta0, v.error / eta0, v.enskog / eta0,
                    v.enskog_ratio, v.enskog_ratio_error, coll / v.value});
  }
  analysis::write_csv("viscosity_3d.csv",
                      {"packing", "chi", "eta_over_eta0", "error", "enskog_over_eta0",
                       "over_enskog", "over_enskog_error", "collisional_share"},
                      rows);
  fmt::print("\n{:.1f} s\n",
             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return 0;
}
