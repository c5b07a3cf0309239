// hypergas/granular/theory.hpp -- kinetic theory of granular (inelastic hard-sphere) gases in
// D dimensions: the homogeneous cooling state (HCS), the white-noise-driven steady state,
// the cooling rate, Haff's law and the Enskog collision frequency. Header-only.
//
// Conventions (those of the engines): equal masses m = 1, k_B = 1, restitution coefficient
// alpha in [0, 1]; a collision with unit normal n turns g = v1 - v2 into
// g' = g - (1 + alpha)(g.n) n, so it loses the energy (1 - alpha^2)(g.n)^2 / 4.
// Temperature T = <v^2>/D, thermal speed v_T = sqrt(2T), scaled velocity c = v / v_T.
// The distribution is expanded in Sonine polynomials of x = c^2,
//   f(v) = phi(v) [1 + a2 S2(x) + a3 S3(x) + ...],
//   S2(x) = x^2/2 - (D+2) x/2 + D(D+2)/8,
//   S3(x) = -x^3/6 + (D+4) x^2/4 - (D+2)(D+4) x/8 + D(D+2)(D+4)/48,
// (phi the Maxwellian at T; the convention of van Noije & Ernst 1998, Brilliantov &
// Poeschel 2000 and Santos & Montanero 2009), which gives exactly
//   <v^4> = D(D+2) T^2 (1 + a2),   <v^6> = D(D+2)(D+4) T^3 (1 + 3 a2 - a3).
//
// Time unit ("nu_M units"): the mean collision time of the elastic Maxwellian gas at the
// temperature named, as in dsmc/time_unit.hpp: a particle meets partners at the rate
// kappa |g| (kappa = n sigma^(D-1) V_(D-1), V_(D-1) = pi^((D-1)/2) / Gamma((D+1)/2) the
// volume of the unit (D-1)-ball, i.e. the cross-section), and kappa <|g|>_Maxwell(T) = 1.
// In physical units nu_M(T) = Omega_D n sigma^(D-1) sqrt(T/m),
// Omega_D = 2 pi^((D-1)/2) / Gamma(D/2) (analysis/enskog.hpp: boltzmann_rate).
//
// The derivations (and the checks of the quoted literature formulas) are in
// docs/validation.md, section "Granular gases: the homogeneous cooling state and Haff's
// law"; the quadrature checks in tests/unit/test_granular_theory.cpp.
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "hypergas/error.hpp"

namespace hypergas::granular {

namespace detail {
inline void check(double alpha, int d, int min_d = 1) {
  if (!(alpha >= 0.0 && alpha <= 1.0))
    throw InvalidInput("granular theory: alpha must be in [0, 1], got " + std::to_string(alpha));
  if (d < min_d)
    throw InvalidInput("granular theory: D must be >= " + std::to_string(min_d) + ", got " +
                       std::to_string(d));
}
}  // namespace detail

// ---------------------------------------------------------------------------------------
// Cumulants from measured moments
// ---------------------------------------------------------------------------------------

/// a2 from the moments m2 = <v^2>, m4 = <v^4> (any velocity unit, centre-of-mass frame):
/// a2 = D/(D+2) m4/m2^2 - 1, i.e. <v^4> = (1 + a2) D(D+2) T^2 with T = m2/D. Dimensionless;
/// 0 for a Maxwellian.
inline double a2_from_moments(double m2, double m4, int d) {
  return d / (d + 2.0) * m4 / (m2 * m2) - 1.0;
}

/// a3 from m2, m4, m6 = <v^6> in the Sonine convention above (Brilliantov & Poeschel,
/// Phys. Rev. E 61, 2809 (2000); Santos & Montanero, Granular Matter 11, 157 (2009)):
/// <v^6> = D(D+2)(D+4) T^3 (1 + 3 a2 - a3), so
/// a3 = 1 + 3 a2 - D^2 m6 / ((D+2)(D+4) m2^3). Dimensionless; 0 for a Maxwellian.
inline double a3_from_moments(double m2, double m4, double m6, int d) {
  const double a2 = a2_from_moments(m2, m4, d);
  return 1.0 + 3.0 * a2 - static_cast<double>(d) * d * m6 / ((d + 2.0) * (d + 4.0) * m2 * m2 * m2);
}

// ---------------------------------------------------------------------------------------
// Cooling rate, collision frequency, Haff's law
// ---------------------------------------------------------------------------------------

/// Cooling rate zeta = -d ln T / dt in units of nu_M(T), the elastic Maxwellian collision
/// frequency at the current temperature (dimensionless):
///   zeta = (1 - alpha^2)/D * (1 + 3 a2/16 + a3/64)
/// (Sonine, linear in a2 and a3). Derivation: the energy loss per collision averaged over
/// the hard-sphere normals, <(g.n)^2> = 2|g|^2/(D+1), and <|g|^3>/<|g|> = 2 (D+1) T for a
/// Maxwellian, give zeta = (1 - alpha^2)/D; the Sonine terms multiply <|g|^3> by
/// 1 + 3 a2/16 + a3/64 in every D. In the convention of Brey, Dufty & Santos (frequency
/// nu = p/eta_0 = 4/(D+2) nu_M) this is the familiar (D+2)/(4D) (1 - alpha^2)(1 + 3a2/16);
/// in van Noije & Ernst's / Garzo & Dufty's (nu_0 = n sigma^(D-1) sqrt(2T/m)) it is
/// sqrt(2) pi^((D-1)/2)/(D Gamma(D/2)) (1 - alpha^2)(1 + 3a2/16).
inline double cooling_rate(double alpha, int d, double a2, double a3 = 0.0) {
  detail::check(alpha, d);
  return (1.0 - alpha * alpha) / d * (1.0 + 3.0 * a2 / 16.0 + a3 / 64.0);
}

/// Collision frequency of the gas with Sonine coefficients a2, a3 over the Maxwellian one
/// at the same temperature: <|g|>/<|g|>_M = 1 - a2/16 - a3/64 (hard spheres, every D,
/// linear in a2 and a3). The relative velocity of a pair has the distribution
/// phi_rel [1 + (a2/2) S2(y) + (a3/4) S3(y) + ...] in y = |g|^2/(4T), and
/// <y^p S_k(y)>/<y^p> = (-1)^k p(p-1)...(p-k+1)/k! at p = 1/2. Dimensionless.
inline double collision_frequency_ratio(double a2, double a3 = 0.0) {
  return 1.0 - a2 / 16.0 - a3 / 64.0;
}

/// Haff's law T(t) = T0 / (1 + t/t0)^2 in the HCS: with zeta* = cooling_rate(alpha, D, a2)
/// and nu_M(T) proportional to sqrt(T), dT/dt = -zeta* nu_M(T0) sqrt(T/T0) T, so
///   t0 = 2 / zeta*   in mean collision times of the Maxwellian gas at T0 (DSMC units).
/// Throws at alpha = 1 (no cooling).
inline double haff_t0(double alpha, int d, double a2, double a3 = 0.0) {
  const double z = cooling_rate(alpha, d, a2, a3);
  if (!(z > 0.0)) throw InvalidInput("haff_t0: the gas does not cool (alpha = 1)");
  return 2.0 / z;
}

/// T(t)/T0 on Haff's law, t and t0 in the same unit.
inline double haff_temperature_ratio(double t, double t0) {
  const double s = 1.0 + t / t0;
  return 1.0 / (s * s);
}

// ---------------------------------------------------------------------------------------
// Enskog (EDMD) collision frequency
// ---------------------------------------------------------------------------------------

/// Enskog collision frequency per particle of the elastic Maxwellian hard-sphere fluid at
/// packing fraction eta with contact value chi = g(sigma+), in units of 1/(sigma sqrt(m/kT))
/// (the EDMD unit when T = T0):
///   nu_E = chi Omega_D n sigma^(D-1) sqrt(kT/m),  n sigma^D = eta / v_D,
///   v_D = pi^(D/2) / (Gamma(D/2+1) 2^D)  =>  nu_E = D 2^D eta chi / sqrt(pi).
/// 3D: 24 eta chi / sqrt(pi) = 4 n sigma^2 chi sqrt(pi kT/m) (Chapman & Cowling). In a
/// cooling gas nu_E(T) = nu_E(T0) sqrt(T/T0); the Enskog HCS has the Boltzmann a2, and its
/// cooling rate is cooling_rate(...) * nu_E, so Haff's t0 in EDMD units is
/// haff_t0(alpha, D, a2) / enskog_collision_frequency(D, eta, chi).
inline double enskog_collision_frequency(int d, double eta, double chi) {
  return d * std::pow(2.0, d) * eta * chi / std::sqrt(std::numbers::pi);
}

/// Contact value g(sigma+) of hard spheres (3D), Carnahan & Starling, J. Chem. Phys. 51,
/// 635 (1969): chi = (1 - eta/2)/(1 - eta)^3 (Z = 1 + 4 eta chi).
inline double chi_carnahan_starling(double eta) {
  const double u = 1.0 - eta;
  return (1.0 - 0.5 * eta) / (u * u * u);
}

/// Contact value g(sigma+) of hard disks (2D), Henderson, Mol. Phys. 30, 971 (1975):
/// chi = (1 - 7 eta/16)/(1 - eta)^2 (Z = 1 + 2 eta chi = (1 + eta^2/8)/(1 - eta)^2).
inline double chi_henderson(double eta) {
  const double u = 1.0 - eta;
  return (1.0 - 7.0 * eta / 16.0) / (u * u);
}

// ---------------------------------------------------------------------------------------
// Sonine coefficients of the HCS and of the white-noise steady state
// ---------------------------------------------------------------------------------------
// These need D >= 2 (they throw InvalidInput for D = 1): in 1D equal-mass elastic
// collisions only swap velocities: the elastic relaxation of a2,
// d<v^4>/dt = -4 (D - 1) a2 nu_M T^2, vanishes, and the Sonine denominators go to 0 as
// alpha -> 1.

/// First-Sonine a2 of the homogeneous cooling state (dimensionless), van Noije & Ernst,
/// Granular Matter 1, 57 (1998):
///   a2 = 16 (1 - alpha)(1 - 2 alpha^2) / (9 + 24 D - alpha (41 - 8 D) + 30 (1 - alpha) alpha^2).
/// Re-derived (docs/validation.md): the HCS condition d<v^4>/dt = -2 zeta <v^4> with the
/// collisional moments linear in a2 and the a2^2 term of zeta (1 + a2) dropped. 3D:
/// 16 (1-alpha)(1-2alpha^2)/(81 - 17 alpha + 30 alpha^2 (1-alpha)); 2D: denominator
/// 57 - 25 alpha + 30 alpha^2 (1-alpha). Zero at alpha = 1 and at alpha = 1/sqrt(2).
inline double a2_hcs(double alpha, int d) {
  detail::check(alpha, d, 2);
  return 16.0 * (1.0 - alpha) * (1.0 - 2.0 * alpha * alpha) /
         (9.0 + 24.0 * d - alpha * (41.0 - 8.0 * d) + 30.0 * (1.0 - alpha) * alpha * alpha);
}

/// First-Sonine a2 of the steady state driven by a white-noise thermostat (each velocity
/// receives independent Gaussian kicks), van Noije & Ernst 1998; Montanero & Santos,
/// Granular Matter 2, 53 (2000) (dimensionless):
///   a2 = 16 (1 - alpha)(1 - 2 alpha^2) / (73 + 56 D - 3 alpha (35 + 8 D) + 30 (1 - alpha) alpha^2).
/// Re-derived: the noise adds 2(D+2)/D <v^2> q per unit heating q to d<v^4>/dt, so the
/// steady state needs d<v^4>/dt|coll = -2 (D+2)/D zeta <v^2>^2, i.e. the HCS condition
/// without the factor (1 + a2). 3D denominator: 241 - 177 alpha + 30 alpha^2 (1-alpha).
inline double a2_white_noise(double alpha, int d) {
  detail::check(alpha, d, 2);
  return 16.0 * (1.0 - alpha) * (1.0 - 2.0 * alpha * alpha) /
         (73.0 + 56.0 * d - 3.0 * alpha * (35.0 + 8.0 * d) + 30.0 * (1.0 - alpha) * alpha * alpha);
}

/// The HCS in the second Sonine approximation: a2 and a3 (dimensionless).
struct SecondSonine {
  double a2 = 0.0, a3 = 0.0;
};

/// Second-Sonine a2 and a3 of the HCS: the HCS conditions d<v^4>/dt = -2 zeta <v^4> and
/// d<v^6>/dt = -3 zeta <v^6>, with the collisional moments of f = phi [1 + a2 S2 + a3 S3]
/// and zeta linear in (a2, a3) and every product of a2, a3 dropped (the fully linear
/// scheme; derived here by computer algebra in general D, docs/validation.md). The two
/// linear equations, in units nu_M(T) T^2 and nu_M(T) T^3 (s = 1 + alpha):
///   A0 + A2 a2 + A3 a3 = 0,  B0 + B2 a2 + B3 a3 = 0,
///   A0 = (alpha^2 - 1)(2 alpha^2 - 1),
///   A2 = -s (8 D alpha + 24 D - 30 alpha^3 + 30 alpha^2 - 41 alpha + 9)/16,
///   A3 = -s (12 D alpha - 44 D + 10 alpha^3 - 10 alpha^2 + 91 alpha - 59)/64,
///   B0 = 3 (alpha^2 - 1)(8 D alpha^2 - 4 D + 8 alpha^4 + 20 alpha^2 - 13)/4,
///   B2 = -3 s (32 D^2 alpha + 96 D^2 - 280 D alpha^3 + 536 D alpha^2 - 20 D alpha + 212 D
///              - 280 alpha^5 + 280 alpha^4 - 1500 alpha^3 + 1244 alpha^2 + 23 alpha - 343)/64,
///   B3 = 3 s (16 D^2 alpha + 368 D^2 - 280 D alpha^3 + 1048 D alpha^2 - 820 D alpha + 1396 D
///              - 280 alpha^5 + 280 alpha^4 - 3100 alpha^3 + 2332 alpha^2 - 1481 alpha + 521)/256.
/// With a3 = 0 the first equation gives a2_hcs. Example 3D, alpha = 0.5: a2 = 0.04499,
/// a3 = -0.01768 (first Sonine 0.05246).
inline SecondSonine hcs_second_sonine(double alpha, int d) {
  detail::check(alpha, d, 2);
  const double a = alpha, a2 = a * a, a3 = a2 * a, a4 = a2 * a2, a5 = a4 * a;
  const double D = d, D2 = D * D, s = 1.0 + a;
  const double A0 = (a2 - 1.0) * (2.0 * a2 - 1.0);
  const double A2 = -s * (8.0 * D * a + 24.0 * D - 30.0 * a3 + 30.0 * a2 - 41.0 * a + 9.0) / 16.0;
  const double A3 = -s * (12.0 * D * a - 44.0 * D + 10.0 * a3 - 10.0 * a2 + 91.0 * a - 59.0) / 64.0;
  const double B0 = 3.0 * (a2 - 1.0) * (8.0 * D * a2 - 4.0 * D + 8.0 * a4 + 20.0 * a2 - 13.0) / 4.0;
  const double B2 = -3.0 * s *
                    (32.0 * D2 * a + 96.0 * D2 - 280.0 * D * a3 + 536.0 * D * a2 - 20.0 * D * a +
                     212.0 * D - 280.0 * a5 + 280.0 * a4 - 1500.0 * a3 + 1244.0 * a2 + 23.0 * a -
                     343.0) /
                    64.0;
  const double B3 = 3.0 * s *
                    (16.0 * D2 * a + 368.0 * D2 - 280.0 * D * a3 + 1048.0 * D * a2 - 820.0 * D * a +
                     1396.0 * D - 280.0 * a5 + 280.0 * a4 - 3100.0 * a3 + 2332.0 * a2 - 1481.0 * a +
                     521.0) /
                    256.0;
  const double det = A2 * B3 - A3 * B2;
  return {(-A0 * B3 + A3 * B0) / det, (-A2 * B0 + A0 * B2) / det};
}

/// Absolute tolerance band for comparing a measured HCS a2 with a2_hcs(alpha, D):
///   band = 2 |a2_hcs - a2_second_sonine|,
/// twice the change from the first to the second Sonine approximation (the next correction
/// taken to be no larger than the last one). DSMC values of the HCS a2 are published
/// (Brey, Ruiz-Montero & Cubero, Phys. Rev. E 54, 3664 (1996); Montanero & Santos, Granular
/// Matter 2, 53 (2000); Santos & Montanero, Granular Matter 11, 157 (2009)), but their
/// numbers could not be checked here, so the band is derived, not copied
/// (docs/validation.md gives a table).
/// Values: 3D alpha = 0.9: 0.0022, 0.8: 0.0030, 0.5: 0.0149, 0.0: 0.153; 2D alpha = 0.9:
/// 0.0056, 0.5: 0.0349. Zero at alpha = 1, where a2 = 0 exactly; callers add the
/// statistical error of the measurement.
inline double hcs_band(double alpha, int d) {
  return 2.0 * std::abs(a2_hcs(alpha, d) - hcs_second_sonine(alpha, d).a2);
}

}  // namespace hypergas::granular
