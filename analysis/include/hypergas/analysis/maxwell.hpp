// hypergas/analysis/maxwell.hpp -- Maxwell–Boltzmann reference distributions in D dimensions.
//
// For one species of mass m at temperature kT, each velocity component is normal with
// variance kT/m; the speed |v| is a chi distribution with D degrees of freedom scaled by
// sqrt(kT/m); the kinetic energy m v^2 / 2 is Gamma(D/2) with scale kT. Moments:
// <v^2> = D kT/m, <v^4> = D(D+2) (kT/m)^2 (e.g. Cercignani, "The Boltzmann Equation and Its
// Applications", 1988, ch. II; any D follows from the chi distribution).
#pragma once

namespace hypergas::analysis {

/// Which single-particle quantity a histogram or a reference describes.
enum class Quantity {
  speed,      ///< |v|, velocity units
  component,  ///< v_x, velocity units
  energy      ///< m v^2 / 2, energy units
};

/// Name of a quantity ("speed", "component", "energy").
const char* to_string(Quantity q);

/// The Maxwell–Boltzmann distribution of one quantity for dimension `dim` (1..6, any D >= 1
/// works), temperature `kT` (energy units) and particle mass `mass` (mass units).
struct MaxwellReference {
  Quantity quantity = Quantity::speed;
  int dim = 3;        ///< D
  double kT = 1.0;    ///< temperature, energy units (> 0)
  double mass = 1.0;  ///< particle mass, mass units (> 0)

  /// Throws InvalidInput unless dim >= 1 and kT, mass are finite and > 0.
  void validate() const;
  /// Probability density at x (1/velocity for speed and component, 1/energy for energy).
  double pdf(double x) const;
  /// Cumulative probability P(X <= x) (dimensionless).
  double cdf(double x) const;
  /// Upper tail P(X > x), accurate far in the tail (dimensionless).
  double upper_tail(double x) const;
  /// The x with cdf(x) = p, for 0 < p < 1 (units of x).
  double quantile(double p) const;
  /// Exact raw moment <X^k> for k >= 0 (units of x to the k).
  double moment(int k) const;
};

}  // namespace hypergas::analysis
