// hypergas/dsmc/time_unit.hpp -- the DSMC time unit: the equilibrium mean collision time.
//
// Each unordered pair collides at rate c |g|^a / (N - 1), so particle i collides at rate
// c <|g_ij|^a>_j (the mean over the N - 1 others) and the whole gas at (N/2) c <|g|^a>.
// The unit of time is fixed by requiring one collision per particle per unit time in the
// equilibrium that the conserved energy determines: c = 1 / <|g|^a>_eq. In equilibrium the
// relative velocity of a pair of inverse masses w1, w2 is Gaussian with variance kT (w1+w2)
// per component, so |g| / sqrt(kT (w1 + w2)) is chi-distributed with D degrees of freedom:
//     <|g|^a> = (2 kT (w1 + w2))^(a/2) Gamma((D + a)/2) / Gamma(D/2).
// With zero total momentum the energy E = sum m |v|^2 / 2 fills D (N - 1) degrees of
// freedom, kT = 2 E / (D (N - 1)); with this kT, <|g|^2> over all pairs equals its
// equilibrium value exactly. For mixtures the average runs over the pair species with the
// exact finite-N pair fractions n_s (n_t - delta_st) / (N (N - 1)).
// Example: 3D hard spheres, m = kT = 1: <|g|> = 4/sqrt(pi) = 2.2568, c = 0.4431.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "hypergas/error.hpp"
#include "hypergas/particles.hpp"

namespace hypergas::dsmc {

/// <|g|^a> of a Maxwellian pair in D dims whose relative velocity has variance s2 per
/// component (s2 = kT (1/m1 + 1/m2)); velocity units of sqrt(s2).
inline double mean_relative_speed_power(int d, double a, double s2) {
  return std::pow(2.0 * s2, 0.5 * a) * std::exp(std::lgamma(0.5 * (d + a)) - std::lgamma(0.5 * d));
}

/// Equilibrium temperature (energy units) of the particles at zero total momentum:
/// kT = sum m |v|^2 / (D (N - 1)). Requires N >= 2.
template <int D, Features F>
double equilibrium_temperature(const Particles<D, F>& p) {
  double e2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) e2 += p.velocity(i).squaredNorm() / p.inv_mass(i);
  return e2 / (D * (static_cast<double>(p.size()) - 1.0));
}

/// The rate constant c = 1 / <|g|^a>_eq (units: 1 / (velocity^a x mean collision time)) for
/// the particles' conserved energy and species composition.
template <int D, Features F>
double rate_constant(const Particles<D, F>& p, double a) {
  const double n = static_cast<double>(p.size());
  if (p.size() < 2) throw InvalidInput("DSMC needs at least 2 particles");
  const double kT = equilibrium_temperature(p);
  if (!(kT > 0.0) || !std::isfinite(kT))
    throw InvalidInput("DSMC: the gas has no thermal energy (kT must be > 0 and finite)");
  if constexpr (!F.species) {
    return 1.0 / mean_relative_speed_power(D, a, 2.0 * kT);
  } else {
    std::array<double, max_species> cnt{};
    for (std::size_t i = 0; i < p.size(); ++i) cnt[p.species(i)] += 1.0;
    double mean = 0.0;
    for (int s = 0; s < max_species; ++s)
      for (int t = 0; t < max_species; ++t) {
        const double pairs = cnt[s] * (cnt[t] - (s == t ? 1.0 : 0.0)) / (n * (n - 1.0));
        if (pairs > 0.0)
          mean += pairs * mean_relative_speed_power(
                              D, a, kT * (p.species_inv_mass(s) + p.species_inv_mass(t)));
      }
    return 1.0 / mean;
  }
}

/// Throws InvalidInput unless the total momentum is zero to rounding, |P| <= 1e-9
/// sqrt(M sum m |v|^2) (sums in long double), and the velocities are not all zero: the time
/// unit above is defined in the centre-of-mass frame.
template <int D, Features F>
void require_zero_momentum(const Particles<D, F>& p) {
  std::array<long double, D> mom{};
  long double mass = 0.0L, mv2 = 0.0L;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double m = p.mass(i);
    mass += m;
    for (int k = 0; k < D; ++k) {
      const double x = p.velocity(i)[k];
      mom[static_cast<std::size_t>(k)] += m * x;
      mv2 += m * x * x;
    }
  }
  long double p2 = 0.0L;
  for (const long double pk : mom) p2 += pk * pk;
  if (!(mv2 > 0.0L)) throw InvalidInput("velocities must not all be zero");
  if (std::sqrt(static_cast<double>(p2)) > 1e-9 * std::sqrt(static_cast<double>(mass * mv2)))
    throw InvalidInput("the total momentum must be zero (the time unit is defined in the "
                       "centre-of-mass frame): subtract the mass-weighted mean velocity");
}

}  // namespace hypergas::dsmc
