// hypergas/edmd/observables.hpp -- equilibrium relations of hard spheres in D dimensions
// that EDMD measurements are checked against.
//
// Collision virial and collision rate. With r_ij = x_i - x_j at contact (|r_ij| = sigma) and
// dp_i the momentum given to i, P V = N kT + (1/(D t)) sum_coll r_ij . dp_i, so
//     Z - 1 = sum_coll sigma |dp| / (D N kT t).
// In equilibrium the pair velocities at contact are Maxwellian and independent of positions;
// the normal relative speed u of colliding pairs has density ~ u exp(-mu u^2 / (2 kT)) (mu
// the reduced mass), so <|dp|> = 2 mu <u> = sqrt(2 pi mu kT), which is sqrt(pi m kT) for equal
// masses. With N nu t / 2 collisions in time t (nu = collisions per particle per unit time):
//     Z - 1 = (sigma nu / (2 D)) sqrt(pi m / kT)                                     (*)
// Enskog's collision frequency nu = n S_D sigma^(D-1) g(sigma) sqrt(kT / (pi m)) (S_D = D v_D
// the unit-sphere area, n the number density) turned into (*) gives the contact theorem
//     Z - 1 = 2^(D-1) eta g(sigma).
// Both are exact for hard spheres in equilibrium; a run tests (*) by measuring Z from the
// virial and nu from the collision count independently. The engine measures both over a
// window of time (MeasurementWindow, Engine::reset_observables).
#pragma once

#include <cmath>
#include <limits>
#include <cstddef>
#include <cstdint>
#include <numbers>

namespace hypergas::edmd {

/// The window of the collision-virial and collision-rate measurements: its start time, the
/// collision count at its start, and the sum over its collisions of r_ij . dp_i.
struct MeasurementWindow {
  double t0 = 0.0;
  std::uint64_t c0 = 0;
  double virial = 0.0;

  /// Starts a new window at time `now` after `ncoll` collisions.
  void reset(double now, std::uint64_t ncoll) {
    t0 = now;
    c0 = ncoll;
    virial = 0.0;
  }
  std::uint64_t collisions(std::uint64_t ncoll) const { return ncoll - c0; }
  double time(double now) const { return now - t0; }
  /// Reduced pressure Z = PV/(N kT) = 1 + sum_coll r_ij . dp_i / (D N kT t) of n particles
  /// at temperature kT in D dimensions over the window up to `now`.
  double pressure_Z(int D, std::size_t n, double kT, double now) const {
    return 1.0 + virial / (D * static_cast<double>(n) * kT * time(now));
  }
  /// Collisions per particle per unit time in the window (2 per collision).
  double collision_rate(std::size_t n, std::uint64_t ncoll, double now) const {
    return 2.0 * static_cast<double>(collisions(ncoll)) /
           (static_cast<double>(n) * time(now));
  }
};

/// Whether the reduced pressure Z = PV/(N kT) is defined for a gas of restitution alpha
/// under a shear rate `shear_rate` (any units; 0: none): only an elastic gas at rest is in
/// equilibrium. A granular gas cools, and a sheared one has a pressure tensor of the flow
/// (the shear stress, the normal stress differences) and no equilibrium pressure. The one
/// rule for the engine (Engine::pressure_Z_defined), the command and Python.
inline bool has_pressure_Z(double alpha, double shear_rate) {
  return alpha >= 1.0 && shear_rate == 0.0;
}

/// Collision rate per particle (per unit time) implied by Z through (*), for diameter sigma,
/// mass m and temperature kT (equal masses).
inline double rate_from_Z(int D, double Z, double sigma = 1.0, double m = 1.0, double kT = 1.0) {
  return 2.0 * D * (Z - 1.0) / (sigma * std::sqrt(std::numbers::pi * m / kT));
}

/// Reduced pressure implied by a collision rate nu through (*).
inline double Z_from_rate(int D, double nu, double sigma = 1.0, double m = 1.0, double kT = 1.0) {
  return 1.0 + sigma * nu / (2.0 * D) * std::sqrt(std::numbers::pi * m / kT);
}

/// Contact value g(sigma) from Z at packing eta (contact theorem).
inline double contact_value(int D, double Z, double eta) {
  return (Z - 1.0) / (std::pow(2.0, D - 1) * eta);
}

/// Carnahan–Starling equation of state for 3D hard spheres, Z = (1 + eta + eta^2 - eta^3) /
/// (1 - eta)^3 (J. Chem. Phys. 51, 635 (1969)); accurate to ~0.1% in the stable fluid.
inline double carnahan_starling_Z(double eta) {
  return (1.0 + eta + eta * eta - eta * eta * eta) / std::pow(1.0 - eta, 3);
}

/// Henderson's equation of state for hard disks, Z = (1 + eta^2/8) / (1 - eta)^2
/// (D. Henderson, Mol. Phys. 30, 971 (1975)); within ~0.2% of simulation for eta <= 0.5.
inline double henderson_Z(double eta) { return (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta)); }

/// The equation of state the code holds for dimension D at packing eta: Tonks' exact
/// 1 / (1 - eta) (1D rods), Henderson (2D), Carnahan–Starling (3D); NaN for D >= 4, where
/// no closed form of comparable accuracy is included.
inline double reference_Z(int D, double eta) {
  switch (D) {
    case 1: return 1.0 / (1.0 - eta);
    case 2: return henderson_Z(eta);
    case 3: return carnahan_starling_Z(eta);
    default: return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace hypergas::edmd
