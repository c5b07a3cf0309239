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
//
// Sums over particles: a plain left-to-right double sum of N positive terms has a relative
// error that grows like sqrt(N) eps typically and N eps at worst (eps = 2^-53; ~1e-13 and
// ~1e-9 at N = 1e7). RunningSum carries that plain sum together with the exact rounding
// error of each addition, so either can be read: `compensated` is accurate to a few eps
// whatever N is, `plain` reproduces the plain sum bit for bit (the form earlier versions
// wrote, which MomentsRecorder keeps for small N so that its files do not change).
#pragma once

#include <cstddef>
#include <vector>

#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/observer.hpp"

namespace hypergas::analysis {

/// How a sum over particles is read (see the file comment).
enum class Summation {
  plain,       ///< the left-to-right double sum
  compensated  ///< the plain sum plus its accumulated rounding error: accurate to ~eps
};

/// A running sum of doubles that carries the plain sum and, exactly, the rounding error of
/// each addition (Knuth's branch-free TwoSum): `compensated()` is the algorithm Sum2 of
/// Ogita, Rump & Oishi ("Accurate sum and dot product", SIAM J. Sci. Comput. 26:1955, 2005),
/// as accurate as a plain sum in twice the working precision; `plain()` is, bit for bit, the
/// sum `s += x` in the same order. O(1) memory, six flops per term, no branch.
class RunningSum {
 public:
  RunningSum() = default;
  /// A sum known exactly (e.g. n unit masses): plain value x, no rounding error.
  static RunningSum exact(double x) {
    RunningSum r;
    r.s_ = x;
    return r;
  }
  void add(double x) {
    const double t = s_ + x;
    const double z = t - s_;
    c_ += (s_ - (t - z)) + (x - z);  // exactly (s_ + x) - t, what rounding t lost
    s_ = t;
  }
  /// Adds another running sum (its plain value with the rounding error of that addition,
  /// and its own carried error): the compensated value stays accurate to a few eps. The
  /// plain value is then no longer a left-to-right sum of the terms.
  void merge(const RunningSum& o) {
    add(o.s_);
    c_ += o.c_;
  }
  double plain() const { return s_; }
  double compensated() const { return s_ + c_; }
  double value(Summation how) const { return how == Summation::plain ? s_ : s_ + c_; }

 private:
  double s_ = 0.0;  // the plain sum
  double c_ = 0.0;  // sum of the rounding errors of the additions so far
};

/// Throws InvalidInput unless the snapshot is readable (dim >= 1, stride >= dim, velocity
/// array present when n > 0, species index < n_species).
void validate(const Snapshot& s);

/// Number of particles of `species` (all particles for species = -1).
std::size_t count(const Snapshot& s, int species = -1);

/// Mean mass of `species` (all particles for -1), mass units; 1 for a unit-mass gas.
/// Throws InvalidInput if there is none, or one of them has a non-finite or non-positive mass.
double mean_mass(const Snapshot& s, int species = -1, Summation how = Summation::compensated);

/// Temperature kT = sum m v^2 / (D N) over `species` (all for -1), energy units.
double temperature(const Snapshot& s, int species = -1, Summation how = Summation::compensated);

/// One value per particle of `species`: speed or v_x (velocity units, mass-weighted when
/// pooled, see above; the mean mass summed `how`) or kinetic energy m v^2 / 2 (energy
/// units). n values: for large snapshots, prefer a streaming pass (see MomentsRecorder).
std::vector<double> values(const Snapshot& s, Quantity q, int species = -1,
                           Summation how = Summation::compensated);

/// The MB reference for `values(s, q, species)`: kT = temperature(s) of all particles
/// (equilibrium is one temperature for all species) and mass = mean_mass(s, species).
MaxwellReference reference(const Snapshot& s, Quantity q, int species = -1,
                           Summation how = Summation::compensated);

/// Particle counts and the sums of m and m v^2 of every species and of all particles, from
/// one pass over a snapshot (O(n_species) memory): what mean_mass, temperature and count
/// give, for all species at once. Each sum runs in particle order over its own particles,
/// so the plain values equal those of the single-species functions bit for bit.
class SnapshotTotals {
 public:
  /// Reads `s` (validate(s) first). Throws InvalidInput if a particle has a non-finite or
  /// non-positive mass.
  explicit SnapshotTotals(const Snapshot& s);
  /// The same over particles [begin, end) only.
  SnapshotTotals(const Snapshot& s, std::size_t begin, std::size_t end);
  /// Adds the totals of another range of the same snapshot (RunningSum::merge).
  void merge(const SnapshotTotals& o);

  /// Particles of `species` (all for -1; 0 for a species the snapshot does not have).
  std::size_t count(int species = -1) const;
  /// As mean_mass(s, species, how); throws InvalidInput if `species` has no particle.
  double mean_mass(int species = -1, Summation how = Summation::compensated) const;
  /// As temperature(s, species, how); throws InvalidInput if `species` has no particle.
  double temperature(int species = -1, Summation how = Summation::compensated) const;

 private:
  struct Totals {
    std::size_t n = 0;
    RunningSum mass;     // sum of m_i, mass units
    RunningSum twice_e;  // sum of m_i |v_i|^2, energy units
  };
  const Totals* of(int species) const;  // nullptr for a species out of range
  int dim_ = 0;
  std::vector<Totals> t_;  // all particles, then species 0, 1, ...
};

}  // namespace hypergas::analysis
