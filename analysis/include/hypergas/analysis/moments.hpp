// hypergas/analysis/moments.hpp -- velocity moments of a snapshot with standard errors.
//
// Maxwell–Boltzmann values in D dimensions (mass m, temperature kT): m2 = D kT/m,
// m4 = D(D+2) (kT/m)^2, m6 = D(D+2)(D+4) (kT/m)^3, component kurtosis <v_x^4>/<v_x^2>^2 = 3.
// Standard errors treat the particles as independent (exact for DSMC-like product states;
// an underestimate where velocities are correlated).
#pragma once

#include <cstddef>

#include "hypergas/observer.hpp"

namespace hypergas::analysis {

/// An estimate and its standard error (same units).
struct Estimate {
  double value = 0.0;
  double error = 0.0;
};

/// Velocity moments of one species or of all particles.
struct Moments {
  std::size_t n = 0;    ///< particles used
  double kT = 0.0;      ///< temperature sum m v^2 / (D n), energy units
  Estimate m2;          ///< <|v|^2>, velocity^2
  Estimate m4;          ///< <|v|^4>, velocity^4
  Estimate m6;          ///< <|v|^6>, velocity^6
  Estimate kurtosis_x;  ///< <w_x^4> / <w_x^2>^2 of the (mass-weighted) x component, MB: 3
  /// <w^4> / (D(D+2) (kT/m_mean)^2) of mass-weighted velocities (dimensionless, MB: 1;
  /// for one species this is D m4 / ((D+2) m2^2)). Its error ignores the O(1/n) error of kT.
  Estimate m4_ratio;
};

/// Moments of `species` (all particles for -1; pooled values are mass-weighted for
/// kurtosis_x and m4_ratio, raw for m2, m4, m6). Throws InvalidInput if there are < 2.
Moments compute_moments(const Snapshot& s, int species = -1);

}  // namespace hypergas::analysis
