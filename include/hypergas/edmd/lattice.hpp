// hypergas/edmd/lattice.hpp -- initial positions on a D-dimensional lattice in the box.
//
// D <= 2: the simple (hyper)cubic lattice Z^D, nearest-neighbour distance a = L/M.
// D >= 3: the checkerboard lattice D_D (integer points with an even coordinate sum; D_3 is
// fcc), nearest-neighbour distance sqrt(2) a. It holds M^D/2 sites for even M and reaches
// packing fractions 2^(D/2-1) times those of Z^D (0.74, 0.62, 0.47, 0.32 in D = 3..6), so
// most fluid states start without compression. When N is below the number of sites, N
// sites are drawn at random (vacancies spread uniformly).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "hypergas/error.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::edmd {

/// Lattice sites placed in [0, L)^D and the nearest-neighbour distance between sites.
template <int D>
struct LatticeSites {
  std::vector<Vec<D>> x;
  double nearest = 0.0;  ///< length: the largest diameter that fits without overlap
};

/// The number of sites of the lattice with M cells per side in D dimensions: M^D, or M^D / 2
/// for the checkerboard lattice (D >= 3).
inline double lattice_capacity(int D, std::uint64_t M) {
  const double c = std::pow(static_cast<double>(M), D);
  return D >= 3 ? c / 2.0 : c;
}

/// The cells per side of the start lattice for n particles: the smallest M (even for
/// D >= 3) whose lattice holds n. n fills it when lattice_capacity(D, M) == n.
inline std::uint64_t lattice_side(int D, std::size_t n) {
  const std::uint64_t step = D >= 3 ? 2 : 1;
  std::uint64_t M = step;
  while (lattice_capacity(D, M) < static_cast<double>(n)) M += step;
  return M;
}

/// N sites of the lattice described above in a periodic cube of side L (lengths).
template <int D>
LatticeSites<D> lattice_sites(std::size_t n, double L, Rng& rng) {
  if (n == 0) throw InvalidInput("lattice: need at least one particle");
  const bool checker = (D >= 3);
  const std::uint64_t M = lattice_side(D, n);
  // Enumerate sites.
  std::vector<std::uint64_t> sites;
  std::uint64_t total = 1;
  for (int k = 0; k < D; ++k) total *= M;
  sites.reserve(static_cast<std::size_t>(checker ? total / 2 : total));
  for (std::uint64_t q = 0; q < total; ++q) {
    std::uint64_t r = q, sum = 0;
    for (int k = 0; k < D; ++k) {
      sum += r % M;
      r /= M;
    }
    if (!checker || sum % 2 == 0) sites.push_back(q);
  }
  // Random subset of size n (partial Fisher–Yates).
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = k + static_cast<std::size_t>(rng.below(sites.size() - k));
    std::swap(sites[k], sites[j]);
  }
  LatticeSites<D> out;
  const double a = L / static_cast<double>(M);
  out.nearest = checker ? a * std::sqrt(2.0) : a;
  if (sites.size() == 1) out.nearest = L;  // a single particle: only its own images
  out.x.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::uint64_t r = sites[k];
    for (int d = 0; d < D; ++d) {
      out.x[k][d] = (static_cast<double>(r % M) + 0.25) * a;
      r /= M;
    }
  }
  return out;
}

}  // namespace hypergas::edmd
