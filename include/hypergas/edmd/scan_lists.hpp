// hypergas/edmd/scan_lists.hpp -- the neighbour-list scan policy (edmd::ListScan): each
// particle keeps a list of the particles near it, a prediction computes the pair times of
// that list only, and leaving a sphere around the list's centre is the event that renews
// the list. The measured fastest scan for dense fluids (scan.hpp). The policy interface is
// described in scan_slab.hpp.
//
// Each particle i has an anchor a_i, its position when its list was last made, and stays
// within r = shell/2 of it: reaching that distance is i's "crossing" event (Ev::t_cross),
// which re-anchors i at its position and renews its list (relist). Particles i and j are
// listed with each other, in both lists, iff |a_i - a_j| < R = s_max + shell (s_max the
// largest contact distance until the next rebuild of the grid). Then every pair that can
// collide is listed: two particles in contact are s <= s_max apart and each is within r
// of its anchor, so their anchors are less than s_max + 2r = R apart. The correctness of
// one event per particle (engine.hpp) holds as for cells: a pair's listing is fixed while
// neither renews its list, and a renewal is an event that rescans the particle.
//
// The grid files the anchors (cells at least R wide, changed only at a renewal), so that a
// renewal finds the new list among the 3^D cells around the new anchor. Periodic images
// are the minimum image: with 3 or more cells per side, L >= 3 R, and a listed pair is at
// most R + shell < L/2 apart along every axis while both stay near their anchors. Positions
// are brought back into the box at each renewal (State::wrap), so a stored position is at
// most r outside the box.
//
// Pair times are computed as in the cell scans, two at a time without branches
// (contact_times), after the records of the whole list were prefetched. Anchors are
// floats (12 bytes per particle in 3D): a float anchor is within ~1e-7 L of the position it
// was taken from, far inside the sphere of radius r, and every test uses the stored float
// values, so the argument above holds for them exactly. A list has room for K entries, the
// same K for every particle; K grows (all lists copied) when a renewal needs more.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "hypergas/edmd/prediction.hpp"
#include "hypergas/edmd/state.hpp"

namespace hypergas::edmd {

/// Shell width (in units of the largest diameter) of the neighbour lists in dimension D:
/// the listing distance is 1 + shell diameters, and a list is renewed after its particle
/// moved shell/2.
constexpr double list_shell(int D) { return D <= 3 ? 0.5 : D == 4 ? 0.35 : 0.25; }

/// The neighbour-list scan (see the file comment).
template <int D, Features F>
class ListScanner {
 public:
  static constexpr double cells_per_particle = 2.0;
  static constexpr bool keeps_pairs_on_crossing = false;
  /// The engine's crossing event renews the list (relist) instead of moving a cell.
  static constexpr bool lists = true;

  /// Extra cell width beyond the contact distance (length, at unit diameter scale).
  double shell(const State<D, F>& s) const {
    return list_shell(D) * s.max_base;
  }

  /// Anchors every particle at its position (in the box), files the anchors in the grid
  /// and makes every list.
  void rebuilt(State<D, F>& s) {
    const std::size_t n = s.size();
    K_ = 0;
    nb_.clear();
    nn_.assign(n, 0);
    anchor_.assign(n * D, 0.0f);
    if (s.cells.per_side() < 3) return;  // the one-cell box: scan_small_box, no lists
    s.cells.clear();
    for (std::uint32_t i = n; i-- > 0;) {  // lists in slot order
      for (int k = 0; k < D; ++k) anchor_[i * D + k] = static_cast<float>(s.p.position(i)[k]);
      s.cells.insert(i, anchor_cell(s, i));
    }
    // Count first (K = the largest list plus room), then fill.
    std::vector<std::uint32_t> count(n, 0);
    const double R2 = listing_distance2(s);
    for (std::uint32_t i = 0; i < n; ++i)
      for_each_near(s, i, R2, [&](std::uint32_t j) {
        if (j > i) ++count[i], ++count[j];
      });
    std::uint32_t most = 0;
    for (auto c : count) most = std::max(most, c);
    resize_lists(n, most + most / 4 + 4);
    for (std::uint32_t i = 0; i < n; ++i)
      for_each_near(s, i, R2, [&](std::uint32_t j) {
        if (j > i) push(i, j), push(j, i);
      });
  }
  void left_cell(State<D, F>&, std::uint32_t) {}
  /// Renews i's list (i is at now and in the box): i leaves its old neighbours' lists, is
  /// anchored at its position and filed in the anchor's cell, and is listed with every
  /// particle whose anchor is within the listing distance of its own.
  void relist(State<D, F>& s, std::uint32_t i) {
    for (int k = 0; k < D; ++k) anchor_[i * D + k] = static_cast<float>(s.p.position(i)[k]);
    const std::uint32_t c = anchor_cell(s, i);
    if (c != s.cells.cell_of(i)) {
      s.cells.remove(i);
      s.cells.insert(i, c);
    }
    // The new list, then only the lists of the particles that left or joined i's change.
    old_.assign(nb_.data() + std::size_t{i} * K_, nb_.data() + std::size_t{i} * K_ + nn_[i]);
    fresh_.clear();
    for_each_near(s, i, listing_distance2(s), [&](std::uint32_t j) { fresh_.push_back(j); });
    std::sort(old_.begin(), old_.end());
    std::sort(fresh_.begin(), fresh_.end());
    std::size_t a = 0, b = 0;
    while (a < old_.size() || b < fresh_.size()) {
      if (b == fresh_.size() || (a < old_.size() && old_[a] < fresh_[b])) {
        erase(old_[a++], i);  // left
      } else if (a == old_.size() || fresh_[b] < old_[a]) {
        push(fresh_[b++], i);  // joined
      } else {
        ++a, ++b;
      }
    }
    if (fresh_.size() > K_) resize_lists(nn_.size(), static_cast<std::uint32_t>(fresh_.size()) + 8);
    std::copy(fresh_.begin(), fresh_.end(), nb_.data() + std::size_t{i} * K_);
    nn_[i] = static_cast<std::uint16_t>(fresh_.size());
    ++relists_;
  }
  /// Before the collision of i and j: asks for both lists (their entries are read next).
  void prefetch_lists(std::uint32_t i, std::uint32_t j) const {
    for (const std::uint32_t q : {i, j}) {
      const std::uint32_t* row = nb_.data() + std::size_t{q} * K_;
      __builtin_prefetch(row);
      __builtin_prefetch(row + 16);
    }
  }
  /// After the collision, before the scans of i and j: asks for the records of both lists
  /// at once, so that the misses of the second scan overlap the first.
  void prefetch_records(const State<D, F>& s, std::uint32_t i, std::uint32_t j) const {
    prefetch_row(s, i);
    prefetch_row(s, j);
  }
  /// With the particles renumbered (Engine::reorder): rows and anchors move, entries are
  /// renamed.
  void permute(const std::vector<std::uint32_t>& from) {
    const std::size_t n = from.size();
    if (K_ == 0) return;
    std::vector<std::uint32_t> to(n);
    for (std::uint32_t i = 0; i < n; ++i) to[from[i]] = i;
    permute_records(anchor_, from, D);
    permute_records(nn_, from, 1);
    permute_records(nb_, from, static_cast<int>(K_));
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t c = 0; c < nn_[i]; ++c) nb_[i * K_ + c] = to[nb_[i * K_ + c]];
  }
  double bytes_per_particle(const State<D, F>&) const {
    return D * sizeof(float) + sizeof(std::uint16_t) + K_ * sizeof(std::uint32_t);
  }
  /// List renewals since the start, and the current room per list.
  std::uint64_t relists() const { return relists_; }
  std::uint32_t capacity() const { return K_; }

  /// Predicts i's renewal time (leaving the sphere around its anchor) and its pair events
  /// with the particles of its list.
  void scan(ScanState<D, F>& s, std::uint32_t i, int, int, Top2, double sc) {
    const Vec<D> xi = s.p.position(i), vi = s.p.velocity(i);
    const double L = s.L, hL = 0.5 * s.L;
    {  // leaving the sphere of radius shell/2 around the anchor
      Vec<D> d;
      for (int k = 0; k < D; ++k) {
        d[k] = nearest_image(xi[k] - static_cast<double>(anchor_[i * D + k]), L, hL);
      }
      const double r = 0.5 * shell(s);
      const double dd = d.squaredNorm(), dv = d.dot(vi), vv = vi.squaredNorm();
      double t = never;
      if (dd >= r * r && dv >= 0.0) t = 0.0;
      else if (vv > 0.0) t = std::max((std::sqrt(std::max(dv * dv - vv * (dd - r * r), 0.0)) - dv) / vv, 0.0);
      s.ev[i].t_cross = s.now + t;
      s.ev[i].cross = 0;
    }
    const std::uint32_t n = nn_[i];
    const std::uint32_t* row = nb_.data() + std::size_t{i} * K_;
    prefetch_row(s, i);
    s.npairs += n;
    ++s.nscan;
    if (s.dots.size() < 4 * std::size_t{n}) s.dots.resize(4 * std::size_t{n} + 64);
    double* rv = s.dots.data();
    double* vv = rv + n;
    double* rr = vv + n;
    double* tt = rr + n;
    const double now = s.now;
    for (std::uint32_t c = 0; c < n; ++c) {
      const std::uint32_t j = row[c];
      Vec<D> r = s.p.position(j) + s.p.velocity(j) * (now - s.p.local_time(j)) - xi;
      for (int k = 0; k < D; ++k) r[k] = nearest_image(r[k], L, hL);
      const Vec<D> v = s.p.velocity(j) - vi;
      rv[c] = r.dot(v), vv[c] = v.squaredNorm(), rr[c] = r.squaredNorm();
    }
    contact_times(n, rv, vv, rr, sc, s.rate, tt);
    Top2 top;
    for (std::uint32_t c = 0; c < n; ++c)
      if (tt[c] < top.t2) top.offer(tt[c], static_cast<std::int32_t>(row[c]));
    s.store(i, top);
  }

  template <class Archive>
  void io(Archive& a) {
    a.tag("lists");
    a(K_, nb_, nn_, anchor_, relists_);
  }

 private:
  /// x brought to the nearest periodic image, for |x| < 3L/2 (no branch).
  static double nearest_image(double x, double L, double hL) {
    x -= x > hL ? L : 0.0;
    x += x < -hL ? L : 0.0;
    return x;
  }
  /// Asks for the records of every particle on q's list.
  void prefetch_row(const State<D, F>& s, std::uint32_t q) const {
    const std::uint32_t* row = nb_.data() + std::size_t{q} * K_;
    for (std::uint32_t c = 0; c < nn_[q]; ++c) {
      const double* rec = s.p.position(row[c]).data();
      __builtin_prefetch(rec);
      if constexpr (State<D, F>::Store::stride > 8) __builtin_prefetch(rec + 8);
    }
  }
  /// Square of the listing distance R (see the file comment), with a margin for round-off:
  /// the contact distance now plus the shell in a run; the whole cell width while the
  /// diameters grow (the compression stops a stage before s_max exceeds width - shell,
  /// Engine::max_scale_for_cells).
  double listing_distance2(const State<D, F>& s) const {
    const double R = s.rate != 0.0 ? s.cells.width()
                                   : std::min(s.cells.width(),
                                              s.max_base * s.diameter_scale() + shell(s));
    return R * R * (1.0 + 1e-9);
  }
  std::uint32_t anchor_cell(const State<D, F>& s, std::uint32_t i) const {
    std::array<int, D> c;
    for (int k = 0; k < D; ++k) c[k] = s.cells.coord(static_cast<double>(anchor_[i * D + k]));
    return s.cells.index(c);
  }
  /// Calls f(j) for every particle j != i whose anchor is within sqrt(R2) of i's (minimum
  /// image).
  template <class Fn>
  void for_each_near(const State<D, F>& s, std::uint32_t i, double R2, Fn&& f) const {
    const double L = s.L, hL = 0.5 * s.L;
    const float* ai = anchor_.data() + std::size_t{i} * D;
    s.cells.for_each_neighbor(s.cells.coords(s.cells.cell_of(i)), [&](std::uint32_t cell,
                                                                        const Vec<D>&) {
      for (std::int32_t j = s.cells.head(cell); j != Cells<D>::none; j = s.cells.next(j)) {
        if (static_cast<std::uint32_t>(j) == i) continue;
        const float* aj = anchor_.data() + static_cast<std::size_t>(j) * D;
        double d2 = 0.0;
        for (int k = 0; k < D; ++k) {
          const double x =
              nearest_image(static_cast<double>(aj[k]) - static_cast<double>(ai[k]), L, hL);
          d2 += x * x;
        }
        if (d2 < R2) f(static_cast<std::uint32_t>(j));
      }
    });
  }
  /// Removes j from i's list (it is there).
  void erase(std::uint32_t i, std::uint32_t j) {
    std::uint32_t* row = nb_.data() + std::size_t{i} * K_;
    const std::uint32_t last = --nn_[i];
    for (std::uint32_t q = 0; q < last; ++q)
      if (row[q] == j) {
        row[q] = row[last];
        break;
      }
  }
  void push(std::uint32_t i, std::uint32_t j) {
    if (nn_[i] == K_) resize_lists(nn_.size(), K_ + K_ / 2 + 8);
    nb_[std::size_t{i} * K_ + nn_[i]++] = j;
  }
  /// Gives every list room for k entries (k <= 65535), keeping the entries.
  void resize_lists(std::size_t n, std::uint32_t k) {
    k = std::min<std::uint32_t>(k, 65535);
    if (k <= K_) throw std::logic_error("EDMD neighbour list longer than 65535");
    std::vector<std::uint32_t> nb(n * k);
    for (std::size_t i = 0; i < n && K_ > 0; ++i)
      std::copy_n(nb_.data() + i * K_, nn_[i], nb.data() + i * k);
    nb_.swap(nb);
    K_ = k;
  }

  std::uint32_t K_ = 0;                // room per list
  std::vector<std::uint32_t> nb_;      // lists: row i at [i K, i K + nn[i])
  std::vector<std::uint16_t> nn_;      // list lengths
  std::vector<float> anchor_;          // anchors, D per particle
  std::uint64_t relists_ = 0;
  std::vector<std::uint32_t> old_, fresh_;  // scratch of relist
};

/// Scan policy: neighbour lists (ListScanner).
struct ListScan {
  static constexpr std::string_view name = "lists";
  template <int D, Features F>
  using Scanner = ListScanner<D, F>;
};

}  // namespace hypergas::edmd
