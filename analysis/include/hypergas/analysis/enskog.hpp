// hypergas/analysis/enskog.hpp -- the Boltzmann (first Sonine) and Enskog transport
// coefficients of hard spheres in D dimensions, in units sigma = m = kT = 1.
//
// Dilute gas. With the Boltzmann collision frequency nu_B = Omega_D n sigma^(D-1)
// sqrt(kT / m), Omega_D = 2 pi^((D-1)/2) / Gamma(D/2), and the reduced first Sonine values
// eta* = (D + 2)/4, lambda* = D (D + 2)^2 / (8 (D - 1)), D* = D/2 (docs/validation.md),
//   eta_0 = eta* sqrt(m kT) / (Omega_D sigma^(D-1)),  lambda_0 = lambda* k_B sqrt(kT/m) /
//   (Omega_D sigma^(D-1)),  D_0 = D* sqrt(kT/m) / (Omega_D n sigma^(D-1)).
// Dense gas (Enskog). With chi = g(sigma+) and the packing fraction phi, the elastic limit
// of Garzo & Dufty, Phys. Rev. E 59, 5895 (1999), eqs. for eta, kappa and lambda at
// alpha = 1 (first Sonine), is
//   eta / eta_0       = (1 + A_eta)^2 / chi + D / (D + 2) kappa*,   A_eta = 2^D phi chi / (D + 2),
//   lambda / lambda_0 = (1 + A_lam)^2 / chi + (D - 1) / (D + 2) kappa*,
//                                                     A_lam = 3 2^(D-1) phi chi / (D + 2),
//   kappa* = kappa / eta_0 = 2^(2D+2) phi^2 chi / (pi (D + 2))  (bulk viscosity),
//   D_s / D_0         = 1 / chi.
// The three terms are the kinetic-kinetic (1/chi), kinetic-collisional (2A/chi) and
// collisional-collisional parts of the Green-Kubo integral. In 2D they are Gass's hard-disk
// results, eta/eta_0 = 1/chi + 2 phi + (1 + 8/pi) phi^2 chi and lambda/lambda_0 = 1/chi +
// 3 phi + (9/4 + 4/pi) phi^2 chi (J. Chem. Phys. 54, 1898 (1971)); in 3D, with
// y = 4 phi chi, Chapman and Cowling's eta/eta_0 = (1 + 0.8 y + 0.7712 y^2)/chi and
// lambda/lambda_0 = (1 + 1.2 y + 0.7674 y^2)/chi in the first approximation.
#pragma once

#include <cmath>
#include <numbers>

namespace hypergas::analysis::enskog {

/// Omega_D = 2 pi^((D-1)/2) / Gamma(D/2): nu_B = Omega_D n sigma^(D-1) sqrt(kT/m).
inline double omega(int D) {
  return 2.0 * std::pow(std::numbers::pi, 0.5 * (D - 1)) / std::tgamma(0.5 * D);
}
/// Volume of the unit-diameter D-sphere, pi^(D/2) / (Gamma(D/2 + 1) 2^D).
inline double sphere_volume(int D) {
  return std::pow(std::numbers::pi, 0.5 * D) / (std::tgamma(0.5 * D + 1.0) * std::pow(2.0, D));
}
/// Packing fraction of number density n (sigma = 1).
inline double packing(int D, double n) { return n * sphere_volume(D); }
/// Boltzmann collision frequency per particle at number density n (sigma = m = kT = 1).
inline double boltzmann_rate(int D, double n) { return omega(D) * n; }

/// First Sonine dilute values: eta_0, lambda_0 (both density independent) and n D_0.
inline double eta0(int D) { return (D + 2.0) / 4.0 / omega(D); }
inline double lambda0(int D) {
  return D * (D + 2.0) * (D + 2.0) / (8.0 * (D - 1.0)) / omega(D);
}
inline double nD0(int D) { return 0.5 * D / omega(D); }

/// Enskog's factors over the dilute value: the three parts of the Green-Kubo integral.
struct Parts {
  double kinetic = 0.0, cross = 0.0, collisional = 0.0;
  double total() const { return kinetic + cross + collisional; }
};
inline double kappa_star(int D, double phi, double chi) {
  return std::pow(2.0, 2 * D + 2) * phi * phi * chi / (std::numbers::pi * (D + 2.0));
}
inline Parts viscosity(int D, double phi, double chi) {
  const double A = std::pow(2.0, D) * phi * chi / (D + 2.0);
  return {1.0 / chi, 2.0 * A / chi, A * A / chi + D / (D + 2.0) * kappa_star(D, phi, chi)};
}
inline Parts conductivity(int D, double phi, double chi) {
  const double A = 3.0 * std::pow(2.0, D - 1) * phi * chi / (D + 2.0);
  return {1.0 / chi, 2.0 * A / chi,
          A * A / chi + (D - 1.0) / (D + 2.0) * kappa_star(D, phi, chi)};
}
inline double diffusion(double chi) { return 1.0 / chi; }

}  // namespace hypergas::analysis::enskog
