// hypergas/edmd/cells.hpp -- the cell grid of the periodic box: linked cell lists and the
// neighbour-cell stencil with periodic shifts.
//
// The cube of side L is cut into m cells per side of width w = L/m >= s_max (the largest
// contact distance), so two spheres in contact are in the same or adjacent cells. While a
// particle stays in its cell (cell crossings are events) the only periodic image of a
// neighbour it can touch is fixed by the cell offset:
//  * m >= 3: the stencil is the 3^D cells at offsets -1, 0, 1 per axis; crossing the box
//    edge adds a shift of +-L. The image is the "cell image", not the minimum image of the
//    current positions (the two differ when L < 4w, where the minimum image would miss
//    collisions).
//  * fewer than 3 cells fit (2 s_max <= L < 3 s_max): a 2-cell grid would make the offsets
//    -1 and +1 the same cell, and both images of a neighbour can then touch. Such a box is
//    handled as ONE cell whose stencil is the cell itself under all 3^D shifts in
//    {-L, 0, L}^D: every pair is tested against every image that can be within a contact
//    distance (|d_k| < L, so the touching image has shift -L, 0 or +L on each axis), and
//    the box faces are the cell faces, so wrapping across the box is a crossing event.
//    The engine (scan_small_box, prediction.hpp) prunes the shifts per pair: only those
//    whose image can come within a contact distance before the particle's next crossing
//    are tried, typically fewer than one combination per pair instead of 3^D.
// L < 2 s_max is rejected: a sphere would touch its own image.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "hypergas/error.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::edmd {

/// Linked cell lists on an m^D grid (cell index = sum_k c_k m^k).
template <int D>
class Cells {
 public:
  static constexpr std::int32_t none = -1;

  /// Grid for a box of side `L` with cells at least `min_width` wide, for `n` particles,
  /// with at most about `per_particle` cells per particle (memory).
  /// With `extra` > 0 the cells are at least min_width + extra wide (neighbour lists), and a
  /// box of fewer than 3 such cells is one cell.
  void build(double L, double min_width, std::size_t n, double per_particle = 2.0,
             double extra = 0.0) {
    m_ = static_cast<int>(std::floor(L / (min_width + extra) * (1.0 - 1e-12)));
    if (std::floor(L / min_width * (1.0 - 1e-12)) < 2.0)
      throw InvalidInput("box side " + std::to_string(L) + " is below twice the contact distance " +
                         std::to_string(min_width) + ": enlarge N or lower the packing");
    // Cap the number of cells (memory).
    while (m_ > 3 &&
           std::pow(static_cast<double>(m_), D) > per_particle * static_cast<double>(n) + 64.0)
      --m_;
    if (m_ < 3) m_ = 1;  // one cell seen under all 3^D shifts (see the file comment)
    L_ = L;
    w_ = L / m_;
    ncells_ = 1;
    for (int k = 0; k < D; ++k) ncells_ *= static_cast<std::size_t>(m_);
    head_.assign(ncells_, none);
    occupied_.assign((ncells_ + 63) / 64, 0);
    next_.assign(n + 1, none);
    prev_.assign(n, none);
    cell_.assign(n, 0);
    // Stencil offsets {-1,0,1}^D: the 3^D neighbour cells for m >= 3, or the single cell
    // under every shift in {-L,0,L}^D for m = 1.
    const int lo = -1;
    const int span = 3;
    offsets_.clear();
    int total = 1;
    for (int k = 0; k < D; ++k) total *= span;
    for (int q = 0; q < total; ++q) {
      std::array<int, D> o{};
      int r = q;
      for (int k = 0; k < D; ++k) {
        o[k] = lo + r % span;
        r /= span;
      }
      offsets_.push_back(o);
    }
  }

  int per_side() const { return m_; }
  double width() const { return w_; }
  /// Lower and upper face, along one axis, of the cells with coordinate c (the top cells'
  /// upper face is the box side L itself, not m w, which may differ by round-off).
  double face_lo(int c) const { return c * w_; }
  double face_hi(int c) const { return c + 1 == m_ ? L_ : (c + 1) * w_; }
  std::size_t count() const { return ncells_; }

  /// Cell coordinate along one axis of position coordinate x in [0, L] (clamped).
  int coord(double x) const {
    int c = static_cast<int>(std::floor(x / w_));
    return c < 0 ? 0 : (c >= m_ ? m_ - 1 : c);
  }
  /// Cell index from per-axis coordinates.
  std::uint32_t index(const std::array<int, D>& c) const {
    std::uint32_t idx = 0;
    for (int k = D - 1; k >= 0; --k) idx = idx * static_cast<std::uint32_t>(m_) + c[k];
    return idx;
  }
  /// Per-axis coordinates of cell `idx`.
  std::array<int, D> coords(std::uint32_t idx) const {
    std::array<int, D> c{};
    for (int k = 0; k < D; ++k) {
      c[k] = static_cast<int>(idx % static_cast<std::uint32_t>(m_));
      idx /= static_cast<std::uint32_t>(m_);
    }
    return c;
  }

  /// Empties every cell (the grid is kept); particles are then inserted again.
  void clear() {
    std::fill(head_.begin(), head_.end(), none);
    std::fill(occupied_.begin(), occupied_.end(), 0);
    std::fill(next_.begin(), next_.end(), none);
    std::fill(prev_.begin(), prev_.end(), none);
  }
  /// Z-order (Morton) key of a cell: the bits of its D coordinates interleaved, so that
  /// cells near in space are mostly near in key order along every axis.
  std::uint64_t morton(std::uint32_t idx) const {
    const auto c = coords(idx);
    std::uint64_t key = 0;
    // Coordinates are below m <= 2^31; bits beyond 64/D per axis are dropped (they cannot
    // occur for fewer than ~2^64 cells).
    for (int b = 0; b < 64 / D && b < 31; ++b)
      for (int k = 0; k < D; ++k)
        key |= ((static_cast<std::uint64_t>(c[k]) >> b) & 1u) << (b * D + k);
    return key;
  }

  std::uint32_t cell_of(std::uint32_t i) const { return cell_[i]; }
  std::int32_t head(std::uint32_t c) const { return head_[c]; }
  /// Whether cell c has a member: one bit per cell (5.7 kB for the 6^6 cells of a 6D run,
  /// in L1), so that a scan can drop empty cells (half of them at 0.7 members per cell)
  /// before reading their heads.
  bool occupied(std::uint32_t c) const { return (occupied_[c >> 6] >> (c & 63)) & 1u; }
  /// Asks the processor to fetch cell c's list head (scans read many at once).
  void prefetch(std::uint32_t c) const { __builtin_prefetch(&head_[c]); }
  /// The particle after i in its cell's list, or none; next(none) is none, so a scan may
  /// read one link past the end of a list without a branch.
  std::int32_t next(std::int32_t i) const { return next_[static_cast<std::size_t>(i + 1)]; }

  void insert(std::uint32_t i, std::uint32_t c) {
    cell_[i] = c;
    prev_[i] = none;
    next_[i + 1] = head_[c];
    if (head_[c] != none) prev_[head_[c]] = static_cast<std::int32_t>(i);
    head_[c] = static_cast<std::int32_t>(i);
    occupied_[c >> 6] |= std::uint64_t{1} << (c & 63);
  }
  void remove(std::uint32_t i) {
    const std::uint32_t c = cell_[i];
    const std::int32_t nx = next_[i + 1];
    if (prev_[i] != none) next_[static_cast<std::size_t>(prev_[i]) + 1] = nx;
    else head_[c] = nx;
    if (nx != none) prev_[nx] = prev_[i];
    if (head_[c] == none) occupied_[c >> 6] &= ~(std::uint64_t{1} << (c & 63));
  }

  /// Calls f(cell, shift) for every stencil cell of home cell `h` (coordinates), where shift
  /// (a Vec<D>, length) is added to a neighbour's position to get its cell image. When
  /// `axis >= 0` only the cells at offset `dir` along `axis` are visited (the slab a particle
  /// entering `h` along that axis newly sees; m >= 3 only).
  template <class Fn>
  void for_each_neighbor(const std::array<int, D>& h, Fn&& f, int axis = -1, int dir = 0) const {
    for (const auto& o : offsets_) {
      if (axis >= 0 && o[axis] != dir) continue;
      std::array<int, D> c;
      Vec<D> shift = Vec<D>::Zero();
      for (int k = 0; k < D; ++k) {
        int ck = h[k] + o[k];
        if (ck >= m_) {
          ck -= m_;
          shift[k] = L_;
        } else if (ck < 0) {
          ck += m_;
          shift[k] = -L_;
        }
        c[k] = ck;
      }
      f(index(c), shift);
    }
  }

  /// Bytes per particle of the lists (cell id, next, prev) plus the cell heads and bits.
  /// Saves or restores the grid and its lists (member order decides the scan order).
  template <class Archive>
  void io(Archive& a) {
    a.tag("cells");
    a(m_, L_, w_, ncells_, head_, next_, prev_, cell_, occupied_, offsets_);
  }

  double bytes_per_particle(std::size_t n) const {
    return 3.0 * sizeof(std::int32_t) +
           static_cast<double>(ncells_ * sizeof(std::int32_t) + occupied_.size() * 8) /
               static_cast<double>(n);
  }

 private:
  int m_ = 0;
  double L_ = 0.0, w_ = 0.0;
  std::size_t ncells_ = 0;
  std::vector<std::int32_t> head_, next_, prev_;  // next_[i + 1]: after i; next_[0] = none
  std::vector<std::uint32_t> cell_;
  std::vector<std::uint64_t> occupied_;  // bit c: cell c has a member
  std::vector<std::array<int, D>> offsets_;
};

}  // namespace hypergas::edmd
