// hypergas/dsmc/maxwell_theory.hpp -- exact moment relaxation of Maxwell molecules.
//
// Fourth moment, isotropic scattering, equal masses, D dims, time in mean collision times
// (each particle collides at rate 1 with a random partner). A collision keeps
// V = (v + w)/2 and r = |v - w|/2 and sets v' = V + r sigma, sigma uniform on S^(D-1), so
// with E[V.sigma] = 0 and E[(V.sigma)^2] = |V|^2 / D,
//     E_sigma |v'|^4 = (|V|^2 + r^2)^2 + 4 r^2 |V|^2 / D.
// With A = |v|^2, B = |w|^2, c = v.w: |V|^2 + r^2 = (A + B)/2, 16 |V|^2 r^2 = (A+B)^2 - 4c^2.
// Averaging over independent partners of an isotropic law with m2 = <A>, m4 = <A^2>
// (<(A+B)^2> = 2 m4 + 2 m2^2, <c^2> = m2^2 / D), dm4/dt = <|v'|^4 - |v|^4> gives
//     dm4/dt = -(D-1)/(2D) m4 + (D-1)(D+2)/(2 D^2) m2^2
//            = -lambda4 (m4 - m4_eq),  lambda4 = (D - 1)/(2 D),  m4_eq = (D+2)/D m2^2,
// (m4_eq = D (D+2) (kT/m)^2, the Maxwellian value). D = 3: lambda4 = 1/3; D = 1: no
// relaxation. The law must be isotropic (for an anisotropic one <c^2> = tr(P^2) instead).
//
// BKW solution (Bobylev 1975, Dokl. Akad. Nauk SSSR 225; Krook & Wu 1976, PRL 36, 1107),
// in D dims with kT = m = 1: f(v, t) = M_K(v) [a + b |v|^2], M_K the Gaussian of variance K,
// normalisation and energy give b = (1 - K)/(2 K^2), a = 1 - D (1 - K)/(2K), so
// m4 = D (D+2) K (2 - K) and m4 - m4_eq = -D (D+2) (1 - K)^2. The fourth-moment law above then
// requires 1 - K(t) = (1 - K0) exp(-lambda4 t / 2); positivity needs K0 >= D/(D+2).
// D = 3: K = 1 - (2/5) exp(-t/6), the classical result.
#pragma once

#include <cmath>

namespace hypergas::dsmc {

/// Relaxation rate of the fourth moment <|v|^4> of Maxwell molecules with isotropic
/// scattering in D dims, per mean collision time: (D - 1) / (2 D).
constexpr double maxwell_m4_rate(int d) {
  return (d - 1.0) / (2.0 * d);
}

/// BKW parameter K(t) from K0 = D/(D+2) (kT = m = 1), t in mean collision times.
inline double bkw_K(int d, double t) {
  return 1.0 - (2.0 / (d + 2.0)) * std::exp(-0.5 * maxwell_m4_rate(d) * t);
}

/// Exact <|v|^4>(t) of the BKW solution for temperature kT (mass 1).
inline double bkw_m4(int d, double t, double kT = 1.0) {
  const double k = bkw_K(d, t);
  return d * (d + 2.0) * k * (2.0 - k) * kT * kT;
}

}  // namespace hypergas::dsmc
