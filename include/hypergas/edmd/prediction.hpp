// hypergas/edmd/prediction.hpp -- the parts of a prediction that every neighbour scan
// shares: listing the candidates of the chosen stencil cells (gather), computing their pair
// times in a batch (earliest_pairs), and the scan of the one-cell box (scan_small_box).
//
// A scan policy (scan_slab.hpp, scan_horizon.hpp, scan_filtered.hpp) chooses the stencil
// cells and writes them to ScanState::visit; gather lists their members and prefetches
// their records, then earliest_pairs computes, so that the ~13 records of a 3D scan arrive
// together. A scan's pair times are computed two at a time and without data-dependent
// branches (earliest_pairs, contact_times).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "hypergas/edmd/events.hpp"
#include "hypergas/edmd/pair_time.hpp"
#include "hypergas/edmd/path_box.hpp"
#include "hypergas/edmd/state.hpp"

namespace hypergas::edmd {

/// The state as a scan sees it: the shared State and the scratch of a scan (its stencil
/// cells and candidates, and the batch pair times), with the two steps every scan shares.
/// One object: the out-of-line gather reaches the cell lists, the records and the candidate
/// list from one base pointer.
template <int D, Features F>
struct ScanState : State<D, F> {
  using Store = Particles<D, F>;
  using State<D, F>::p;
  using State<D, F>::cells;
  using State<D, F>::L;
  using State<D, F>::now;
  using State<D, F>::rate;
  using State<D, F>::npairs;
  using State<D, F>::nscan;
  using State<D, F>::base_contact;

  /// A stencil cell or a candidate of a scan. A type per engine instantiation, as is its
  /// vector's resize: with one shared type GCC calls resize out of line in gather when a
  /// program has several engines (docs/benchmarks.md, "Tried and rejected").
  struct Cand {
    std::uint32_t j, shift;  // particle (or cell), periodic shift code: 2 bits per axis,
                             // 0 none, 1 = -L, 2 = +L (AxisStep)
  };
  std::vector<Cand> cand;    // candidates [0, ncand)
  std::size_t ncand = 0;
  std::vector<Cand> visit;   // stencil cells (cell, shift)
  std::size_t nvisit = 0;    //   in use: [0, nvisit)
  std::vector<double> dots;  // scratch of earliest_pairs()

  /// Lists the particles of the cells in visit, except i, as the candidates
  /// cand[0, ncand), and prefetches their records (or, records = false, their PBoxes in
  /// `boxes`).
  /// Cells hold 0.5-0.7 particles on average at the benchmark densities (1.3-1.4 in an
  /// occupied one), so a loop per cell would mispredict its exit at most cells: the first
  /// two members are written without a branch (a missing one's `none` is written and not
  /// counted), and only third and later members loop. Heads are prefetched 8 cells ahead.
  /// gather and gather_filtered stay out of line: inlined they are slower
  /// (docs/benchmarks.md, "Tried and rejected"), and profiles name them.
  template <bool records = true>
  [[gnu::noinline]] void gather(std::uint32_t i, const PBox* boxes = nullptr) {
    (void)boxes;
    std::size_t n = 0;
    const auto me = static_cast<std::int32_t>(i);
    auto fetch = [&](std::int32_t j) {
      const auto jj = static_cast<std::size_t>(j < 0 ? 0 : j);
      if constexpr (!records) {  // FilteredScan: the path box (one line), not the record
        __builtin_prefetch(&boxes[jj]);
      } else {
        const double* rec = p.position(jj).data();
        __builtin_prefetch(rec);
        if constexpr (Store::stride > 8) __builtin_prefetch(rec + 8);  // 4D-6D: 2 lines
      }
    };
    if (cand.size() < 2 * nvisit + 1) cand.resize(2 * nvisit + 64);
    const std::size_t nv = nvisit;
    constexpr std::size_t ahead = 8;
    for (std::size_t v = 0; v < std::min(ahead, nv); ++v) cells.prefetch(visit[v].j);
    for (std::size_t v = 0; v < nv; ++v) {
      const Cand& c = visit[v];
      cells.prefetch(visit[std::min(v + ahead, nv - 1)].j);
      std::int32_t j = cells.head(c.j);
      fetch(j);
      cand[n] = {static_cast<std::uint32_t>(j), c.shift};
      n += static_cast<std::size_t>((j != Cells<D>::none) & (j != me));
      j = cells.next(j);
      fetch(j);
      cand[n] = {static_cast<std::uint32_t>(j), c.shift};
      n += static_cast<std::size_t>((j != Cells<D>::none) & (j != me));
      for (j = cells.next(j); j != Cells<D>::none; j = cells.next(j)) {  // next(none) = none
        // room for this member and the first two members of the cells still to come
        if (cand.size() < n + 2 * (nv - v) + 1) cand.resize(2 * cand.size());
        fetch(j);
        cand[n] = {static_cast<std::uint32_t>(j), c.shift};
        n += static_cast<std::size_t>(j != me);
      }
    }
    ncand = n;
  }

  /// Earliest two pair events of i (at now) with the candidates cand[0, ncand), offered
  /// to `top`. Three passes: the dot products of every pair (straight-line code), their
  /// contact times without branches (contact_times), then the two smallest. Same times as
  /// State::pair_time, bit for bit. Counts the scan and its pairs.
  Top2 earliest_pairs(std::uint32_t i, double sc, Top2 top) {
    const std::size_t n = ncand;
    npairs += n;
    ++nscan;
    if (dots.size() < 4 * n) dots.resize(4 * n);
    double* rv = dots.data();
    double* vv = rv + n;
    double* rr = vv + n;
    double* tt = rr + n;
    const Vec<D> xi = p.position(i), vi = p.velocity(i);
    const double shv[4] = {0.0, -L, L, 0.0};
    for (std::size_t c = 0; c < n; ++c) {
      const std::uint32_t j = cand[c].j;
      Vec<D> shift;
      for (int k = 0; k < D; ++k) shift[k] = shv[(cand[c].shift >> (2 * k)) & 3u];
      const Vec<D> r =
          p.position(j) + p.velocity(j) * (now - p.local_time(j)) + shift - xi;
      const Vec<D> v = p.velocity(j) - vi;
      rv[c] = r.dot(v), vv[c] = v.squaredNorm(), rr[c] = r.squaredNorm();
    }
    contact_times(n, rv, vv, rr, sc, rate, tt);
    for (std::size_t c = 0; c < n; ++c)
      if (tt[c] < top.t2) top.offer(tt[c], static_cast<std::int32_t>(cand[c].j));
    return top;
  }
};

/// Scan of the one-cell box (fewer than 3 cells per side, cells.hpp), for every scan
/// policy. Every other particle j is a neighbour under the 3^D shifts {-L,0,L}^D, but only
/// a few shifts can matter before i's next crossing (after which i scans again): along axis
/// k the relative coordinate d_k + u_k t, t in [0, H], H = time to i's crossing, must come
/// within the largest contact distance of the horizon for shift S_k to give a contact.
/// Typically fewer than one shift combination per pair survives, instead of 3^D (729 in
/// 6D). Every collision is still found: a collision at t* is predicted by the scan of i or
/// j at the later of their last events, whose horizon reaches t*.
template <int D, Features F>
void scan_small_box(State<D, F>& s, std::uint32_t i, double sc) {
  s.predict_crossing(i);
  Ev& e = s.ev[i];
  const double H = e.t_cross - s.now;
  const Vec<D> xi = s.p.position(i);
  const Vec<D> vi = s.p.velocity(i);
  Top2 top;
  for (std::int32_t j = s.cells.head(0); j != Cells<D>::none; j = s.cells.next(j)) {
    if (static_cast<std::uint32_t>(j) == i) continue;
    const Vec<D> d = s.pos_now(static_cast<std::size_t>(j)) - xi;
    const Vec<D> u = s.p.velocity(j) - vi;
    const double b = s.base_contact(i, j);
    const double smax = b * (sc + (s.rate > 0.0 ? s.rate * H : 0.0));
    std::array<std::array<double, 3>, D> opts;
    std::array<int, D> cnt{};
    bool any = true;
    for (int k = 0; k < D && any; ++k) {
      const double ext = u[k] == 0.0 ? 0.0 : u[k] * H;  // inf * 0 would be NaN
      const double lo = std::min(d[k], d[k] + ext), hi = std::max(d[k], d[k] + ext);
      for (const double S : {0.0, -s.L, s.L})
        if (lo + S < smax && hi + S > -smax) opts[k][cnt[k]++] = S;
      any = cnt[k] > 0;
    }
    if (!any) continue;
    std::array<int, D> at{};
    for (;;) {  // odometer over the surviving shift combinations
      Vec<D> shift;
      for (int k = 0; k < D; ++k) shift[k] = opts[k][at[k]];
      top.offer(s.pair_time(i, static_cast<std::uint32_t>(j), shift, sc), j);
      int k = 0;
      while (k < D && ++at[k] == cnt[k]) at[k++] = 0;
      if (k == D) break;
    }
  }
  s.store(i, top);
}

}  // namespace hypergas::edmd
