// hypergas/edmd/given_state.hpp -- an EDMD start from given positions and velocities (a
// state read from a file: `--init-file`, hg.EDMD.from_state), with the check that no two
// spheres overlap.
//
// The box is the periodic cube of side `box` the positions lie in; the spheres have
// diameter 1 (the engine's length unit), so the packing fraction is N v_D(1/2) / box^D and
// follows from the file. Velocities are taken as given: a state written by hypergas (kT = 1
// by construction) continues unchanged, a foreign one keeps its temperature, and EDMD's
// time unit sigma sqrt(m / kT) is then that of kT = 1 in the file's velocity units.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "hypergas/error.hpp"

namespace hypergas::edmd {

/// A given state: n particles, positions[i * D + k] in [0, box), velocities likewise;
/// species[i] (0 or 1) where the engine has two species, else nullptr.
struct GivenState {
  const double* positions = nullptr;
  const double* velocities = nullptr;
  std::size_t n = 0;
  double box = 0.0;
  const std::uint8_t* species = nullptr;
};

/// Two spheres closer than their diameter 1: their numbers and their distance.
struct Overlap {
  std::size_t i = 0, j = 0;
  double distance = 0.0;
};

/// The first overlapping pair of n unit-diameter spheres at `x` in the periodic cube of side
/// L (minimum image), closer than 1 - tol; nothing if there is none. A cell grid of side at
/// least 1: O(N 3^D).
template <int D>
std::optional<Overlap> first_overlap(const double* x, std::size_t n, double L, double tol) {
  const auto dist2 = [&](std::size_t i, std::size_t j) {
    double r2 = 0.0;
    for (int a = 0; a < D; ++a) {
      double d = x[i * D + std::size_t(a)] - x[j * D + std::size_t(a)];
      d -= L * std::round(d / L);
      r2 += d * d;
    }
    return r2;
  };
  const double lim = (1.0 - tol) * (1.0 - tol);
  const long m = static_cast<long>(std::floor(L));  // cells per side, each of side >= 1
  if (m < 3 || n < 64) {                             // small: every pair
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (const double r2 = dist2(i, j); r2 < lim) return Overlap{i, j, std::sqrt(r2)};
    return std::nullopt;
  }
  const auto cell_of = [&](std::size_t i, int a) {
    long c = static_cast<long>(std::floor(x[i * D + std::size_t(a)] / L * double(m)));
    return std::clamp(c, 0l, m - 1);
  };
  const auto key = [&](const long* c) {
    std::uint64_t k = 0;
    for (int a = 0; a < D; ++a) k = k * std::uint64_t(m) + std::uint64_t(c[a]);
    return k;
  };
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;
  cells.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    long c[D];
    for (int a = 0; a < D; ++a) c[a] = cell_of(i, a);
    cells[key(c)].push_back(static_cast<std::uint32_t>(i));
  }
  long nb = 1;
  for (int a = 0; a < D; ++a) nb *= 3;
  for (std::size_t i = 0; i < n; ++i) {
    long c[D];
    for (int a = 0; a < D; ++a) c[a] = cell_of(i, a);
    for (long t = 0; t < nb; ++t) {
      long o[D], r = t;
      for (int a = 0; a < D; ++a) {
        o[a] = ((c[a] + (r % 3) - 1) % m + m) % m;
        r /= 3;
      }
      const auto it = cells.find(key(o));
      if (it == cells.end()) continue;
      for (std::uint32_t j : it->second)
        if (j > i)
          if (const double r2 = dist2(i, j); r2 < lim) return Overlap{i, j, std::sqrt(r2)};
    }
  }
  return std::nullopt;
}

/// Checks a given state for an EDMD start of D dimensions: finite values, positions in
/// [0, box), a box that holds a diameter-1 sphere's cell grid, no overlap. Throws
/// InvalidInput with one line naming the first problem (for an overlap: the pair and by how
/// much).
template <int D>
void check_given_state(const GivenState& g) {
  if (g.n < 2) throw InvalidInput("EDMD start: needs at least 2 particles");
  if (!(g.box > 1.0 && std::isfinite(g.box)))
    throw InvalidInput("EDMD start: the box side must be finite and above the diameter 1, got " +
                       std::to_string(g.box));
  for (std::size_t k = 0; k < g.n * D; ++k) {
    if (!std::isfinite(g.positions[k]) || !std::isfinite(g.velocities[k]))
      throw InvalidInput("EDMD start: particle " + std::to_string(k / D) +
                         " has a position or velocity that is not finite");
    if (!(g.positions[k] >= 0.0 && g.positions[k] < g.box))
      throw InvalidInput("EDMD start: particle " + std::to_string(k / D) +
                         " lies outside the box [0, " + std::to_string(g.box) + ")");
  }
  // a relative 1e-12 of the diameter: the rounding of positions written to 17 digits
  if (const auto o = first_overlap<D>(g.positions, g.n, g.box, 1e-12))
    throw InvalidInput("EDMD start: particles " + std::to_string(o->i) + " and " +
                       std::to_string(o->j) + " overlap: their distance " +
                       std::to_string(o->distance) + " is below the diameter 1 by " +
                       std::to_string(1.0 - o->distance));
}

}  // namespace hypergas::edmd
