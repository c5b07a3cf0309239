// hypergas/analysis/sample.hpp -- per-particle values of a snapshot and its temperature.
//
// The reference temperature is taken from the snapshot itself, kT = 2 E_kin / (D N) with
// E_kin = sum_i m_i v_i^2 / 2, so comparisons with Maxwell–Boltzmann need no parameter.
// Note: a finite closed gas with fixed energy (and zero total momentum) relaxes to the
// microcanonical distribution, not exactly MB; the difference is O(1/N) and invisible to
// KS or chi-square at N ~ 1e5 (the KS statistic resolves ~1/sqrt(N)).
//
// Mixtures: "pooled" values (species = -1) are mass-weighted so that every species has the
// same reference: a velocity v_i of mass m_i becomes v_i sqrt(m_i / m_mean), m_mean the mean
// mass; for one species this is the plain velocity. Energies need no weighting.
#pragma once

#include <cstddef>
#include <vector>

#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/observer.hpp"

namespace hypergas::analysis {

/// Throws InvalidInput unless the snapshot is readable (dim >= 1, stride >= dim, velocity
/// array present when n > 0, species index < n_species).
void validate(const Snapshot& s);

/// Number of particles of `species` (all particles for species = -1).
std::size_t count(const Snapshot& s, int species = -1);

/// Mean mass of `species` (all particles for -1), mass units; 1 for a unit-mass gas.
double mean_mass(const Snapshot& s, int species = -1);

/// Temperature kT = sum m v^2 / (D N) over `species` (all for -1), energy units.
double temperature(const Snapshot& s, int species = -1);

/// One value per particle of `species`: speed or v_x (velocity units, mass-weighted when
/// pooled, see above) or kinetic energy m v^2 / 2 (energy units).
std::vector<double> values(const Snapshot& s, Quantity q, int species = -1);

/// The MB reference for `values(s, q, species)`: kT = temperature(s) of all particles
/// (equilibrium is one temperature for all species) and mass = mean_mass(s, species).
MaxwellReference reference(const Snapshot& s, Quantity q, int species = -1);

}  // namespace hypergas::analysis
