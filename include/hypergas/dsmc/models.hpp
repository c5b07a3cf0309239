// hypergas/dsmc/models.hpp -- collision models: compile-time pieces of the DSMC engine.
//
// A model fixes (i) the pair collision rate q(g) = c |g|^a / (N - 1) per unordered pair
// (c is the time-unit constant of dsmc/time_unit.hpp) and (ii) the law of the scattered
// relative velocity (dsmc/scattering.hpp):
//   HardSpheres          a = 1, specular reflection at a hard-sphere normal;
//   MaxwellMolecules     a = 0, isotropic scattering (VSS with alpha = 1): every candidate
//                        collides, no majorant and no rejection are compiled in;
//   VariableHardSpheres  0 <= a <= 1 (runtime), isotropic scattering (Bird's VHS).
// What the rest of the code needs to know of a model is on its type: `exponent()` (a),
// `isotropic_scattering` (the law of g', from which with a the analysis computes the first
// Sonine transport values) and `supports_drive` (the white-noise drive of dsmc/granular.hpp,
// whose strength comes from the hard-sphere Sonine theory).
// `accept(g2, u, bound)` decides a candidate pair with |g|^2 = g2 against the majorant
// bound G >= |g| for a uniform u in [0, 1): accepted with probability (|g|/G)^a. Hard
// spheres compare squares, so rejected candidates cost no square root.
#pragma once

#include <cmath>
#include <string>
#include <string_view>

#include "hypergas/dsmc/scattering.hpp"
#include "hypergas/error.hpp"

namespace hypergas::dsmc {

/// Hard spheres: rate proportional to |g|, specular reflection.
struct HardSpheres {
  static constexpr bool needs_majorant = true;
  static constexpr std::string_view name = "hs";
  static constexpr std::string_view help = "hard spheres: pair rate ~ |g|, specular reflection";
  static constexpr bool isotropic_scattering = false;
  static constexpr bool supports_drive = true;
  /// The exponent a of the rate |g|^a.
  static constexpr double exponent() { return 1.0; }
  /// Accept with probability |g| / G: (u G)^2 < |g|^2.
  static bool accept(double g2, double u, double bound) { return u * u * bound * bound < g2; }
  /// New relative velocity for relative velocity g with |g| = gnorm > 0.
  template <int D, class G>
  static Vec<D> deflect(const Vec<D>& g, double gnorm, G& rng) {
    return hard_sphere_deflection<D>(g, gnorm, rng);
  }
};

/// Maxwell molecules: rate independent of g, isotropic scattering.
struct MaxwellMolecules {
  static constexpr bool needs_majorant = false;
  static constexpr std::string_view name = "maxwell";
  static constexpr std::string_view help =
      "Maxwell molecules: pair rate independent of |g|, isotropic scattering";
  static constexpr bool isotropic_scattering = true;
  static constexpr bool supports_drive = false;
  static constexpr double exponent() { return 0.0; }
  static bool accept(double, double, double) { return true; }
  template <int D, class G>
  static Vec<D> deflect(const Vec<D>&, double gnorm, G& rng) {
    return isotropic_deflection<D>(gnorm, rng);
  }
};

/// Variable hard spheres: rate proportional to |g|^a, 0 <= a <= 1, isotropic scattering.
class VariableHardSpheres {
 public:
  static constexpr bool needs_majorant = true;
  static constexpr std::string_view name = "vhs";
  static constexpr std::string_view help =
      "variable hard spheres: pair rate ~ |g|^a (--vhs-exponent a), isotropic scattering";
  static constexpr bool isotropic_scattering = true;
  static constexpr bool supports_drive = false;
  /// Throws InvalidInput unless 0 <= a <= 1.
  explicit VariableHardSpheres(double a = 0.5) : a_(a), half_a_(0.5 * a) {
    if (!(a >= 0.0 && a <= 1.0)) throw InvalidInput("VHS exponent must be in [0, 1]");
  }
  double exponent() const { return a_; }
  /// Accept with probability (|g| / G)^a = (g2 / G^2)^(a/2).
  bool accept(double g2, double u, double bound) const {
    return u < std::pow(g2 / (bound * bound), half_a_);
  }
  template <int D, class G>
  static Vec<D> deflect(const Vec<D>&, double gnorm, G& rng) {
    return isotropic_deflection<D>(gnorm, rng);
  }

 private:
  double a_;
  double half_a_;
};

/// What the engine needs of a model type (the three above; registry.hpp lists them).
template <class M>
concept CollisionModel = requires(const M m, double x) {
  { M::name } -> std::convertible_to<std::string_view>;
  { M::help } -> std::convertible_to<std::string_view>;
  { M::needs_majorant } -> std::convertible_to<bool>;
  { M::isotropic_scattering } -> std::convertible_to<bool>;
  { M::supports_drive } -> std::convertible_to<bool>;
  { m.exponent() } -> std::convertible_to<double>;
  { m.accept(x, x, x) } -> std::convertible_to<bool>;
};

}  // namespace hypergas::dsmc
