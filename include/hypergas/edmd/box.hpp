// hypergas/edmd/box.hpp -- the periodic hypercubic box, packing fractions and the packing
// bounds the command line checks --packing against.
//
// Units: diameter sigma = 1 (lengths), packing fraction eta = N v_D(sigma/2) / L^D with v_D
// the volume of a D-ball of that radius.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string>

#include "hypergas/error.hpp"
#include "hypergas/geometry.hpp"

namespace hypergas::edmd {

/// Side L of the periodic cube holding `n` spheres of diameter `sigma` at packing fraction
/// `eta` in D dimensions (length unit of sigma).
inline double box_side(int D, std::size_t n, double eta, double sigma = 1.0) {
  return std::pow(static_cast<double>(n) * ball_volume(D, sigma) / eta, 1.0 / D);
}

/// Packing fraction of `n` spheres of diameter `sigma` in a cube of side L.
inline double packing_fraction(int D, std::size_t n, double L, double sigma = 1.0) {
  return static_cast<double>(n) * ball_volume(D, sigma) / std::pow(L, D);
}

/// Densest known packing fraction in D dimensions (lattice packings Z, A2, D3 = fcc, D4,
/// D5, E6; Conway & Sloane, "Sphere Packings, Lattices and Groups", 3rd ed., Table 1.2).
/// Proven optimal for D = 1, 2, 3 (Hales 2005) and, among lattices, up to D = 8.
inline double densest_packing(int D) {
  constexpr double pi = 3.14159265358979323846;
  static const std::array<double, 7> v = {0.0,
                                          1.0,
                                          pi / (2.0 * std::sqrt(3.0)),
                                          pi / (3.0 * std::sqrt(2.0)),
                                          pi * pi / 16.0,
                                          pi * pi * std::sqrt(2.0) / 30.0,
                                          pi * pi * pi * std::sqrt(3.0) / 144.0};
  if (D < 1 || D > 6) throw InvalidInput("densest_packing: dimension must be 1..6");
  return v[static_cast<std::size_t>(D)];
}

/// Jamming (random close packing) fraction of monodisperse hard spheres, the largest
/// --packing the command line accepts: a disordered fluid compressed by Lubachevsky–
/// Stillinger jams here. D = 3..6: Skoge, Donev, Stillinger & Torquato, Phys. Rev. E 74,
/// 041127 (2006), Table I (phi_J = 0.64, 0.46, 0.31, 0.20). D = 2: monodisperse disks
/// jam near 0.82-0.84 (Berryman, Phys. Rev. A 27, 1053 (1983): 0.82). D = 1: rods fill the
/// line (1, excluded: a box must leave room to move).
inline double jamming_packing(int D) {
  static const std::array<double, 7> v = {0.0, 1.0, 0.82, 0.64, 0.46, 0.31, 0.20};
  if (D < 1 || D > 6) throw InvalidInput("jamming_packing: dimension must be 1..6");
  return v[static_cast<std::size_t>(D)];
}

/// Throws InvalidInput unless 0 < eta < jamming_packing(D).
inline void check_packing(int D, double eta) {
  if (!(std::isfinite(eta) && eta > 0.0))
    throw InvalidInput("packing fraction must be finite and > 0");
  if (eta >= jamming_packing(D))
    throw InvalidInput("packing fraction " + std::to_string(eta) + " is at or above the " +
                       std::to_string(D) + "D jamming density " +
                       std::to_string(jamming_packing(D)) + " (Skoge et al. 2006)");
}

}  // namespace hypergas::edmd
