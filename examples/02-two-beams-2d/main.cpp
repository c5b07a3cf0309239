// Example 02 -- 2D hard disks relaxing from two beams.
//
// The story. Two cold beams of hard disks stream through each other along x: half the
// particles move at +u, half at -u, with a small thermal spread. All the kinetic energy is
// in the x direction (T_x >> T_y), and the x velocities are bimodal. Collisions turn the
// relative motion sideways: first the temperatures T_x = <v_x^2> and T_y = <v_y^2> meet
// (isotropisation), then the shape of the distribution relaxes (the kurtosis of v_x goes
// from about 1 for two sharp beams to 3 for a Gaussian). Both happen within a few mean
// collision times, the second more slowly than the first.
//
// The velocity-space DSMC engine simulates the spatially homogeneous Boltzmann equation for
// hard disks (pair rate ~ |g|) exactly in time; the unit of time is the equilibrium mean
// collision time. A small Observer computes the two directional temperatures from each
// snapshot; the analysis library's MomentsRecorder adds the kurtosis and the distance from
// Maxwell–Boltzmann.
//
// Usage: example_02 [--short]   (writes two_beams_2d.csv in the current folder)
#include <cmath>
#include <cstring>
#include <fmt/core.h>

#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/dsmc/engine.hpp"

using namespace hypergas;

/// Records T_x = <v_x^2> and T_y = <v_y^2> (unit mass, energy units) at each snapshot.
class DirectionalTemperature final : public Observer {
 public:
  void observe(const Snapshot& s) override {
    double tx = 0.0, ty = 0.0;
    for (std::size_t i = 0; i < s.n; ++i) {
      const double* v = s.velocities + i * static_cast<std::size_t>(s.stride);
      tx += v[0] * v[0];
      ty += v[1] * v[1];
    }
    tx_.push_back(tx / static_cast<double>(s.n));
    ty_.push_back(ty / static_cast<double>(s.n));
  }
  std::vector<double> tx_, ty_;
};

int main(int argc, char** argv) {
  const bool short_run = argc > 1 && std::strcmp(argv[1], "--short") == 0;
  dsmc::Config cfg;
  cfg.n = short_run ? 5000 : 100000;
  cfg.init = InitialState::beams;  // +-u e_x, thermal spread kT_spread / kT_drift = 0.05
  cfg.seed = 2;
  const double until = 12.0, every = 0.1;

  dsmc::Engine<2, dsmc::HardSpheres> gas(cfg);
  analysis::MomentsRecorder moments;
  DirectionalTemperature temps;
  // Two observers, one callback: FanOut hands each snapshot (and each request for the
  // engine's tally) to both.
  FanOut both({&moments, &temps});
  gas.run_until(until, &both, every);

  const auto t = moments.column("time"), k = moments.column("kurtosis_x");
  const auto l1 = moments.column("l1_speed");
  std::vector<std::vector<double>> rows;
  for (std::size_t i = 0; i < t.size(); ++i)
    rows.push_back({t[i], temps.tx_[i], temps.ty_[i], temps.tx_[i] / temps.ty_[i], k[i], l1[i]});
  analysis::write_csv("two_beams_2d.csv",
                      {"time", "T_x", "T_y", "anisotropy", "kurtosis_x", "l1_speed"}, rows);

  fmt::print("2D hard disks from two counter-streaming beams, N = {}\n", cfg.n);
  fmt::print("{:>5}  {:>7}  {:>7}  {:>9}  {:>10}  {:>8}\n", "time", "T_x", "T_y", "T_x/T_y",
             "kurtosis_x", "L1(MB)");
  for (std::size_t i = 0; i < t.size(); i += (t.size() - 1) / 16)
    fmt::print("{:>5.1f}  {:>7.4f}  {:>7.4f}  {:>9.3f}  {:>10.3f}  {:>8.3f}\n", t[i], temps.tx_[i],
               temps.ty_[i], temps.tx_[i] / temps.ty_[i], k[i], l1[i]);

  // What you should see: T_x starts near 1.9 kT and T_y near 0.09 kT (the beams' spread);
  // their ratio falls from ~20 to 1 within about 5 collision times, while T_x + T_y = 2 kT
  // stays constant (energy conservation). The kurtosis of v_x starts near 1 (two sharp
  // peaks) and climbs to 3 more slowly than the temperatures meet: the shape relaxes after
  // the second moments. The L1 distance from MB falls to the sampling-noise floor.
  // Check (the example's test): the final anisotropy is within 5 standard errors of 1
  // (standard error of T_x/T_y for N Gaussian components: 2/sqrt(N)), and the energy per
  // particle T_x + T_y equals 2 kT = 2 to 1e-12.
  const double aniso = temps.tx_.back() / temps.ty_.back();
  const double se = 2.0 / std::sqrt(static_cast<double>(cfg.n));
  const double energy = temps.tx_.back() + temps.ty_.back();
  const bool ok = std::abs(aniso - 1.0) < 5 * se && std::abs(energy - 2.0) < 1e-12 * cfg.n;
  fmt::print("{}\n", ok ? "as expected: isotropic and Maxwellian" : "UNEXPECTED: see CSV");
  return ok ? 0 : 1;
}
