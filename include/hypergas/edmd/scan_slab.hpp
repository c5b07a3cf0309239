// hypergas/edmd/scan_slab.hpp -- the slab scan policy (edmd::SlabScan): a prediction scans
// the whole 3^D stencil, and a cell crossing keeps the still-valid pair events and scans
// only the newly adjacent slab of 3^(D-1) cells. The measured fastest scan in D <= 2
// (scan.hpp).
//
// A scan policy is a type with a `name` and a class template Scanner<D, F> that holds the
// policy's own data and provides (Engine calls these; grids of 3 or more cells per side
// only, the one-cell box takes scan_small_box under every policy):
//   cells_per_particle        the cap on cells per particle of the grid (Cells::build)
//   keeps_pairs_on_crossing   whether a crossing keeps valid pair events (slab scan only)
//   rebuilt(s)                after the grid was rebuilt and before the first scan
//   left_cell(s, c)           after a particle left cell c by a crossing
//   permute(from)             with the particles renumbered (Engine::reorder)
//   bytes_per_particle(s)     the policy's persistent bytes per particle
//   scan(s, i, axis, dir, top, sc)   the prediction of i's pair events and crossing (s a
//                                    ScanState, prediction.hpp)
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "hypergas/edmd/prediction.hpp"
#include "hypergas/edmd/state.hpp"

namespace hypergas::edmd {

/// The hooks of a scan policy that keeps no data of its own (slab and horizon scans): a
/// grid of at most 2 cells per particle, nothing to update, permute or count.
template <int D, Features F>
struct StatelessScanner {
  static constexpr double cells_per_particle = 2.0;
  void rebuilt(State<D, F>&) {}
  void left_cell(State<D, F>&, std::uint32_t) {}
  void permute(const std::vector<std::uint32_t>&) {}
  double bytes_per_particle(const State<D, F>&) const { return 0.0; }
  template <class Archive>
  void io(Archive&) {}  // scratch only
};

/// The slab scan (see the file comment).
template <int D, Features F>
class SlabScanner : public StatelessScanner<D, F> {
 public:
  static constexpr bool keeps_pairs_on_crossing = true;

  /// Scans the neighbour cells of i (all, or the slab `dir` along `axis`), keeping the
  /// earliest pair events if they beat `top` (relative times); then predicts the crossing.
  void scan(ScanState<D, F>& s, std::uint32_t i, int axis, int dir, Top2 top,
            double sc) {
    // Two passes: list the candidates and prefetch their records, then compute. A record
    // is one cache line in 3D, and outside the L2 cache a scan's ~13 records arrive
    // together instead of one miss after another.
    const auto h = s.cells.coords(s.cells.cell_of(i));
    s.visit.clear();
    s.cells.for_each_neighbor(
        h,
        [&](std::uint32_t cell, const Vec<D>& shift) {
          s.cells.prefetch(cell);
          std::uint32_t code = 0;  // the 2-bit shift codes of the horizon scan (AxisStep)
          for (int k = 0; k < D; ++k)
            code |= (shift[k] < 0.0 ? 1u : shift[k] > 0.0 ? 2u : 0u) << (2 * k);
          s.visit.push_back({cell, code});
        },
        axis, dir);
    s.nvisit = s.visit.size();
    s.gather(i);
    s.store(i, s.earliest_pairs(i, sc, top));
    s.predict_crossing(i);
  }
};

/// Scan policy: the slab scan (SlabScanner).
struct SlabScan {
  static constexpr std::string_view name = "slab";
  template <int D, Features F>
  using Scanner = SlabScanner<D, F>;
};

}  // namespace hypergas::edmd
