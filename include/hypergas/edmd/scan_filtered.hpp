// hypergas/edmd/scan_filtered.hpp -- the filtered scan policy (edmd::FilteredScan): the
// horizon scan (scan_horizon.hpp), and a stencil cell, then a particle, is skipped when the
// box bounding its members' paths is farther than a contact distance from the scanner's
// box. The measured fastest scan from 4D on (scan.hpp). The policy interface is described
// in scan_slab.hpp.
//
// Each particle keeps the box bounding its path to its next crossing (PBox, 16 bytes,
// path_box.hpp) and each cell the union of its members' boxes: a stencil cell, then a
// member, whose box is farther than a contact distance from the scanner's is skipped
// (drop_far_cells, gather_filtered). The filter needs 5 or more cells per side (the levels
// of PBox); with fewer the scan is the horizon scan, the boxes still kept.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "hypergas/edmd/path_box.hpp"
#include "hypergas/edmd/prediction.hpp"
#include "hypergas/edmd/scan_horizon.hpp"
#include "hypergas/edmd/state.hpp"

namespace hypergas::edmd {

/// The filtered scan (see the file comment).
template <int D, Features F>
class FilteredScanner {
 public:
  /// A 16-byte box per cell: at most 1.5 cells per particle (24 bytes).
  static constexpr double cells_per_particle = 1.5;
  static constexpr bool keeps_pairs_on_crossing = false;

  /// Sets the grid of the boxes and every particle's box: every box is needed before the
  /// first scan.
  void rebuilt(State<D, F>& s) {
    const std::size_t n = s.size();
    box_levels_ = 256.0 * std::max(1, s.cells.per_side() / 5) / s.L;
    pbox_.resize(n);
    cbox_.assign(s.cells.count(), PBox{});
    for (std::uint32_t i = 0; i < n; ++i) {
      s.predict_crossing(i);
      set_path_box(s, i, s.ev[i].t_cross - s.now);
    }
  }
  /// A member left cell c: its box is recomputed (the new cell's box follows i's scan).
  void left_cell(State<D, F>& s, std::uint32_t c) { update_cell_box(s, c); }
  void permute(const std::vector<std::uint32_t>& from) { permute_records(pbox_, from, 1); }
  double bytes_per_particle(const State<D, F>& s) const {
    const double n = static_cast<double>(s.size());
    return sizeof(PBox) * (1.0 + static_cast<double>(cbox_.size()) / n);
  }

  /// The horizon scan's stencil, then (5 or more cells per side) the path-box filter of
  /// the cells and of their members.
  void scan(ScanState<D, F>& s, std::uint32_t i, int, int, Top2, double sc) {
    const bool filter = s.cells.per_side() >= 5;
    const auto [H, smax] = horizon_.stencil(s, i, sc);
    const PBox probe = set_path_box(s, i, H);  // kept even if not used now
    if (filter) {
      // smax <= cell width, so r <= 256 p / m + 2 <= 54 levels
      const auto r = static_cast<std::int32_t>(std::ceil(smax * box_levels_)) + 1;
      drop_far_cells(s, probe, r * r);
      gather_filtered(s, i, probe, r * r);
    } else {
      s.gather(i);
    }
    s.store(i, s.earliest_pairs(i, sc, Top2{}));
  }

 private:
  /// Writes i's path box for the next H time units (i at now) and returns its probe.
  PBox set_path_box(State<D, F>& s, std::uint32_t i, double H) {
    const double q = box_levels_;
    const Vec<D> x = s.p.position(i);
    const Vec<D> v = s.p.velocity(i);
    PBox mine{}, probe{};
    for (int k = 0; k < D; ++k) {  // outward to the grid; u8 casts take levels mod 2^8
      const auto [lo, hi] = HorizonScanner<D, F>::path_extent(x[k], v[k], H);
      const auto glo = static_cast<std::int64_t>(std::floor(std::max(lo, 0.0) * q));
      const auto ghi = static_cast<std::int64_t>(std::ceil(std::min(hi, s.L) * q));
      mine.v[2 * k] = static_cast<std::uint8_t>(glo);
      mine.v[2 * k + 1] = static_cast<std::uint8_t>(-ghi);
      probe.v[2 * k] = static_cast<std::uint8_t>(ghi);
      probe.v[2 * k + 1] = static_cast<std::uint8_t>(-glo);
    }
    pbox_[i] = mine;
    update_cell_box(s, s.cells.cell_of(i));
    return probe;
  }
  /// Recomputes cell c's box, the union of its members' path boxes (cbox_): after a
  /// member's box changed (set_path_box) or a member left (left_cell). An empty cell keeps
  /// a stale box; scans skip it by its occupancy bit.
  void update_cell_box(const State<D, F>& s, std::uint32_t c) {
    std::int32_t j = s.cells.head(c);
    if (j == Cells<D>::none) return;
    PBox u = pbox_[static_cast<std::size_t>(j)];
    for (j = s.cells.next(j); j != Cells<D>::none; j = s.cells.next(j))
      u = PBox::unite(u, pbox_[static_cast<std::size_t>(j)]);
    cbox_[c] = u;
  }
  /// Drops from s.visit the cells whose box (the union of their members' path boxes) is
  /// farther than the contact distance from the scanner's: none of their members could
  /// pass gather_filtered. In 6D about 170 occupied cells of a scan come here.
  void drop_far_cells(ScanState<D, F>& s, const PBox& probe, std::int32_t bound) {
    const std::size_t nv = s.nvisit;
    constexpr std::size_t ahead = 8;
    for (std::size_t v = 0; v < std::min(ahead, nv); ++v)
      __builtin_prefetch(&cbox_[s.visit[v].j]);
    std::size_t n = 0;
    for (std::size_t v = 0; v < nv; ++v) {
      __builtin_prefetch(&cbox_[s.visit[std::min(v + ahead, nv - 1)].j]);
      const auto cell = s.visit[v];
      s.visit[n] = cell;
      n += static_cast<std::size_t>(PBox::near(cbox_[cell.j], probe, bound));
    }
    s.nvisit = n;
  }
  /// ScanState::gather for the filtered scan: a member j is a candidate only if
  /// PBox::near(j's box, the scanner's probe) holds. Two passes: list every member and
  /// prefetch its box (the boxes of a 6D scan's ~230 members are mostly outside L2), then
  /// keep the near ones; records are prefetched for those only.
  [[gnu::noinline]] void gather_filtered(ScanState<D, F>& s, std::uint32_t i,
                                         const PBox& probe, std::int32_t bound) {
    s.template gather<false>(i, pbox_.data());
    const PBox* box = pbox_.data();
    std::size_t n = 0;
    for (std::size_t k = 0; k < s.ncand; ++k) {
      const auto cand = s.cand[k];
      s.cand[n] = cand;
      n += static_cast<std::size_t>(PBox::near(box[cand.j], probe, bound));
    }
    s.ncand = n;
    for (std::size_t k = 0; k < n; ++k) {
      const double* rec = s.p.position(s.cand[k].j).data();
      __builtin_prefetch(rec);
      if constexpr (Particles<D, F>::stride > 8) __builtin_prefetch(rec + 8);
    }
  }


 public:
  /// Saves or restores the path boxes (the horizon walk holds scratch only).
  template <class Archive>
  void io(Archive& a) {
    a.tag("filtered-scan");
    a(pbox_, cbox_, box_levels_);
  }

 private:
  HorizonScanner<D, F> horizon_;  // the stencil walk
  std::vector<PBox> pbox_;        // each particle's path box,
  std::vector<PBox> cbox_;        //   each cell's union of its members' boxes
  double box_levels_ = 0.0;       //   and its grid levels per unit length
};

/// Scan policy: the filtered scan (FilteredScanner).
struct FilteredScan {
  static constexpr std::string_view name = "filtered";
  template <int D, Features F>
  using Scanner = FilteredScanner<D, F>;
};

}  // namespace hypergas::edmd
