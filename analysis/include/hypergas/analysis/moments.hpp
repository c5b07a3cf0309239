// hypergas/analysis/moments.hpp -- velocity moments of a snapshot with standard errors.
//
// Maxwell–Boltzmann values in D dimensions (mass m, temperature kT): m2 = D kT/m,
// m4 = D(D+2) (kT/m)^2, m6 = D(D+2)(D+4) (kT/m)^3, component kurtosis <v_x^4>/<v_x^2>^2 = 3.
// Standard errors treat the particles as independent (exact for DSMC-like product states;
// an underestimate where velocities are correlated).
//
// The moments come from power sums accumulated in one streaming pass (MomentSums), so they
// need O(1) memory whatever the number of particles; the sums are RunningSums (sample.hpp),
// read plain or compensated.
#pragma once

#include <utility>

#include <cstddef>

#include "hypergas/analysis/sample.hpp"
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

/// The sums over n particles behind Moments, in one velocity unit: |v|^2k (k = 1, 2, 3, 4,
/// 6), mass-weighted |w|^4 and |w|^8 and w_x^2k (k = 1..4) with w = v sqrt(m / m_mean),
/// and sum m v^2 (mass times velocity^2).
struct PowerSums {
  double n = 0.0;
  double s2 = 0.0, s4 = 0.0, s6 = 0.0, s8 = 0.0, s12 = 0.0;
  double w4 = 0.0, w8 = 0.0;
  double x2 = 0.0, x4 = 0.0, x6 = 0.0, x8 = 0.0;
  double twice_e = 0.0;
};

/// The moments of `p` for dimension `dim` and mean mass `m_mean`, with the velocity unit
/// of the sums times `scale` (a velocity of 1 in the sums' unit is `scale` velocity
/// units: the moments of velocity^2k are multiplied by scale^2k at the end, so sums of
/// scaled velocities neither overflow nor lose precision). Throws InvalidInput for n < 2.
Moments moments_from_sums(int dim, double m_mean, const PowerSums& p, double scale = 1.0);

/// The power sums behind Moments, fed one particle at a time (the streaming core of
/// compute_moments; a caller that makes its own pass over the particles, such as
/// MomentsRecorder, adds them as it goes). `m_mean` is the mean mass (mass units) of the
/// particles that will be added: it weights w = v sqrt(m / m_mean).
class MomentSums {
 public:
  MomentSums(int dim, double m_mean) : dim_(dim), m_mean_(m_mean) {}

  /// Adds one particle: velocity v[0..dim) (velocity units), inverse mass inv_m (1/mass
  /// units, finite and > 0). Returns |v|^2, summed over components in order.
  double add(const double* v, double inv_m) { return add_impl<false>(v, inv_m); }
  /// add(v, 1.0) without its divisions (the same values bit for bit): unit-mass gases.
  double add_unit_mass(const double* v) { return add_impl<true>(v, 1.0); }

  /// Particles added so far.
  std::size_t count() const { return n_; }
  /// Adds the sums of another set of particles (same dim and m_mean; RunningSum::merge).
  void merge(const MomentSums& o) {
    for (auto [a, b] : {std::pair{&s2_, &o.s2_}, {&s4_, &o.s4_}, {&s6_, &o.s6_}, {&s8_, &o.s8_},
                        {&s12_, &o.s12_}, {&w4_, &o.w4_}, {&w8_, &o.w8_}, {&x2_, &o.x2_},
                        {&x4_, &o.x4_}, {&x6_, &o.x6_}, {&x8_, &o.x8_}, {&twice_e_, &o.twice_e_}})
      a->merge(*b);
    n_ += o.n_;
  }

  /// The moments of the particles added, with sums read `how`. Throws InvalidInput if
  /// fewer than 2 were added.
  Moments result(Summation how = Summation::compensated) const;

 private:
  template <bool Unit>
  double add_impl(const double* v, double inv_m) {
    double vv = 0.0;
    for (int k = 0; k < dim_; ++k) vv += v[k] * v[k];
    const double f = Unit ? unit_f_ : 1.0 / (inv_m * m_mean_);  // w = v sqrt(f)
    const double v4 = vv * vv, v6 = v4 * vv;
    s2_.add(vv);
    s4_.add(v4);
    s6_.add(v6);
    s8_.add(v4 * v4);
    s12_.add(v6 * v6);
    const double ww4 = v4 * f * f;
    w4_.add(ww4);
    w8_.add(ww4 * ww4);
    const double xx = v[0] * v[0] * f;
    x2_.add(xx);
    x4_.add(xx * xx);
    x6_.add(xx * xx * xx);
    x8_.add(xx * xx * xx * xx);
    twice_e_.add(Unit ? vv : vv / inv_m);
    ++n_;
    return vv;
  }

  int dim_;
  double m_mean_;
  double unit_f_ = 1.0 / (1.0 * m_mean_);  // f of a unit mass
  std::size_t n_ = 0;
  // Raw |v|^2k (and squares), mass-weighted |w|^4, w_x^2k, and sum m v^2.
  RunningSum s2_, s4_, s6_, s8_, s12_, w4_, w8_, x2_, x4_, x6_, x8_, twice_e_;
};

/// Moments of `species` (all particles for -1; pooled values are mass-weighted for
/// kurtosis_x and m4_ratio, raw for m2, m4, m6), all sums (the mean mass included) read
/// `how`. One pass for the mean mass, one for the power sums; O(1) memory. Throws
/// InvalidInput if there are < 2.
Moments compute_moments(const Snapshot& s, int species = -1,
                        Summation how = Summation::compensated);

}  // namespace hypergas::analysis
