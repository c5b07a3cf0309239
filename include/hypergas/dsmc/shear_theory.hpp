// hypergas/dsmc/shear_theory.hpp -- exact rheology of Maxwell molecules in uniform shear
// flow, D >= 2 (derived in docs/validation.md, "Uniform shear flow").
//
// Time in mean collision times, one species, isotropic scattering (the engine's maxwell
// model), N particles at zero total momentum. With P = sum v v^T / (N - 1) (its trace / D is
// the engine's temperature T) the Kac process of N particles gives, exactly for the mean,
//     dP/dt = -r (P - T I) - a (e_x e_y^T P + P e_y e_x^T) - 2 zeta P,
// r = N / (2 (N - 1)) (1/2 for N -> infinity), a the shear rate and zeta the thermostat rate.
// Without thermostat (zeta = 0) the mean obeys this linear law at every N; with the
// Gaussian thermostat zeta = -a P_xy / (D T) is the instantaneous ratio of sums, whose mean
// differs from the ratio of means by O(1/N).
// Steady state of p-reduced P* = P / T (the same with the thermostat, and without it in the
// state where T grows as exp(2 zeta t), since for Maxwell molecules r does not depend on T):
//     P*_yy = P*_zz = r / (r + 2 zeta),   P*_xy = -a r / (r + 2 zeta)^2,
//     P*_xx = D - (D - 1) P*_yy,          zeta (r + 2 zeta)^2 = a^2 r / D,
// the cubic of the thermostat rate (one positive root). In 3D, with zeta~ = zeta / r and
// a~ = a / r, zeta~ = (2/3) sinh^2[(1/6) arccosh(1 + 9 a~^2)] (Garzo and Santos, Kinetic
// Theory of Gases in Shear Flows, Kluwer 2003, ch. 2). The shear viscosity
// eta(a) = -P_xy / a (units of p and the mean collision time) against eta(0) = 1 / r gives
// viscosity ratio r^2 / (r + 2 zeta)^2 = (P*_yy)^2; the heating rate without thermostat is
// d ln T / dt = -2 a P*_xy / D = 2 zeta.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace hypergas::dsmc {

/// The relaxation rate r of the traceless pressure tensor of N Maxwell molecules (per mean
/// collision time): N / (2 (N - 1)); n <= 0 gives the Boltzmann limit 1/2.
inline double maxwell_stress_rate(double n) { return n > 1.0 ? n / (2.0 * (n - 1.0)) : 0.5; }

/// The steady uniform shear flow of Maxwell molecules (see the file comment).
struct MaxwellShear {
  double zeta = 0.0;  ///< thermostat rate (per mean collision time); heating rate is 2 zeta
  double pxx = 1.0, pyy = 1.0, pzz = 1.0, pxy = 0.0;  ///< P_ij / p (pzz: each of z, w, ...)
  double viscosity_ratio = 1.0;  ///< eta(a) / eta(0)
};

/// The steady state at shear rate a in D dims for N particles (n <= 0: N -> infinity).
inline MaxwellShear maxwell_shear(int d, double a, double n = 0.0) {
  const double r = maxwell_stress_rate(n);
  const double rhs = a * a * r / d;
  // f(z) = z (r + 2 z)^2 - rhs is increasing for z >= 0: bisection, then Newton polish
  double lo = 0.0, hi = std::max(1.0, std::cbrt(rhs));
  while (hi * (r + 2 * hi) * (r + 2 * hi) < rhs) hi *= 2.0;
  for (int k = 0; k < 200 && hi - lo > 1e-17 * hi; ++k) {
    const double z = 0.5 * (lo + hi);
    (z * (r + 2 * z) * (r + 2 * z) < rhs ? lo : hi) = z;
  }
  double z = 0.5 * (lo + hi);
  for (int k = 0; k < 3 && z > 0.0; ++k) {
    const double f = z * (r + 2 * z) * (r + 2 * z) - rhs;
    const double df = (r + 2 * z) * (r + 2 * z) + 4 * z * (r + 2 * z);
    z -= f / df;
  }
  MaxwellShear s;
  s.zeta = z;
  s.pyy = s.pzz = r / (r + 2 * z);
  s.pxy = -a * r / ((r + 2 * z) * (r + 2 * z));
  s.pxx = d - (d - 1) * s.pyy;
  s.viscosity_ratio = s.pyy * s.pyy;
  return s;
}

/// The uniform shear flow of inelastic Maxwell molecules without thermostat (docs/
/// validation.md, "Uniform shear flow", granular): the engine's maxwell model with
/// restitution alpha, whose collision gives the pair (1 + alpha)/2 of the isotropic elastic
/// change of g. With beta = (1 + alpha)/2, nu_P = r beta (2 - beta) and nu_T = r beta^2 the
/// collisions give dP/dt = -nu_P P + nu_T T I exactly for the mean (alpha = 1: -r (P - T I)),
/// and the flow's linear law has P growing as exp(growth t) in the state
///     P*_yy = P*_zz = nu_T / u,   P*_xy = -a nu_T / u^2,   P*_xx = D - (D - 1) P*_yy,
///     (u - nu_T) u^2 = 2 a^2 nu_T / D,   growth = u - nu_P   (the root u > nu_T),
/// where viscous heating and collisional cooling balance when growth = 0:
/// a^2 = D nu_P^2 (nu_P - nu_T) / (2 nu_T). alpha = 1 is maxwell_shear with growth 2 zeta.
struct MaxwellGranularShear {
  double growth = 0.0;  ///< d ln T / dt, per mean collision time (negative: cooling)
  double pxx = 1.0, pyy = 1.0, pzz = 1.0, pxy = 0.0;  ///< P_ij / p
};

inline MaxwellGranularShear maxwell_granular_shear(int d, double a, double alpha,
                                                   double n = 0.0) {
  const double r = maxwell_stress_rate(n);
  const double beta = 0.5 * (1.0 + alpha);
  const double nu_p = r * beta * (2.0 - beta), nu_t = r * beta * beta;
  const double rhs = 2.0 * a * a * nu_t / d;
  // f(u) = (u - nu_t) u^2 - rhs increases for u >= nu_t: bisection, then Newton polish
  double lo = nu_t, hi = nu_t + std::max(1.0, std::cbrt(rhs));
  while ((hi - nu_t) * hi * hi < rhs) hi *= 2.0;
  for (int k = 0; k < 200 && hi - lo > 1e-17 * hi; ++k) {
    const double u = 0.5 * (lo + hi);
    ((u - nu_t) * u * u < rhs ? lo : hi) = u;
  }
  double u = 0.5 * (lo + hi);
  for (int k = 0; k < 3; ++k) u -= ((u - nu_t) * u * u - rhs) / (3.0 * u * u - 2.0 * nu_t * u);
  MaxwellGranularShear s;
  s.growth = u - nu_p;
  s.pyy = s.pzz = nu_t / u;
  s.pxy = -a * nu_t / (u * u);
  s.pxx = d - (d - 1) * s.pyy;
  return s;
}

/// The mean pressure tensor without thermostat at time t from P = T0 I (elastic, one
/// species): {P_xx, P_xy, P_yy, P_zz} / T0, the exact solution of the linear law above
/// (Runge-Kutta of order 4 in steps of at most 1e-3 mean collision times: error < 1e-12).
inline std::array<double, 4> maxwell_shear_moments(int d, double a, double n, double t) {
  const double r = maxwell_stress_rate(n);
  using V = std::array<double, 4>;
  const auto f = [&](const V& p) {
    const double T = (p[0] + p[2] + (d - 2) * p[3]) / d;
    return V{-2 * a * p[1] - r * (p[0] - T), -a * p[2] - r * p[1], -r * (p[2] - T),
             -r * (p[3] - T)};
  };
  V p{1.0, 0.0, 1.0, 1.0};
  const int steps = std::max(1, static_cast<int>(std::ceil(t / 1e-3)));
  const double h = t / steps;
  for (int k = 0; k < steps; ++k) {
    const V k1 = f(p);
    V q;
    for (int i = 0; i < 4; ++i) q[i] = p[i] + 0.5 * h * k1[i];
    const V k2 = f(q);
    for (int i = 0; i < 4; ++i) q[i] = p[i] + 0.5 * h * k2[i];
    const V k3 = f(q);
    for (int i = 0; i < 4; ++i) q[i] = p[i] + h * k3[i];
    const V k4 = f(q);
    for (int i = 0; i < 4; ++i) p[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  return p;
}

}  // namespace hypergas::dsmc
