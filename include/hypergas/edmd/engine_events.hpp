// hypergas/edmd/engine_events.hpp -- the event kernel of edmd::Engine (engine.hpp): one
// event (step_event), a collision (collide; its granular velocity update stays in the class),
// a cell crossing (cross), the rebuild of cells and calendar, the prefetches ahead of the
// next events (look_ahead) and the Z-order renumbering (reorder). Member definitions out of
// the class, inline as they were inside it; engine.hpp includes this header after the class,
// so include engine.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "hypergas/edmd/engine.hpp"

namespace hypergas::edmd {

template <int D, Features F, class Scan>
template <bool Record>
inline void Engine<D, F, Scan>::step_event() {
  if (s_.ncoll >= next_reorder_) reorder();
  const std::uint32_t i = q_.top();
  look_ahead();
  s_.now = q_.top_time();
  Ev& e = s_.ev[i];
  if (e.t_pair <= e.t_cross) {
    const std::int32_t j = e.partner;
    if (!e.valid(s_.cnt)) {
      ++s_.nstale;
      if (e.valid2(s_.cnt)) {
        // The runner-up of i's last scan is still valid: every pair with a particle that
        // has not changed course since that scan is at least that late, and a pair with
        // one that has was scanned by it (see the file comment). No rescan needed.
        e.t_pair = e.t_pair2, e.partner = e.partner2, e.pcount = e.pcount2;
        e.t_pair2 = never, e.partner2 = -1;
        q_.update(i, std::min(e.t_pair, e.t_cross));
        return;
      }
      s_.advance(i);
      predict(i);
      return;
    }
    if constexpr (lists) scanner_.prefetch_lists(i, static_cast<std::uint32_t>(j));
    collide<Record>(i, static_cast<std::uint32_t>(j));
    if constexpr (lists) scanner_.prefetch_records(s_, i, static_cast<std::uint32_t>(j));
    predict(i);
    predict(static_cast<std::uint32_t>(j));
    if (debug_) check_overlaps();
  } else {
    ++s_.ncross;
    cross(i);
    if (debug_) check_overlaps();
  }
}

template <int D, Features F, class Scan>
inline void Engine<D, F, Scan>::rebuild() {
  const std::size_t n = size();
  for (std::uint32_t i = 0; i < n; ++i) {
    if (le_.on()) [[unlikely]] wrap_sheared(i);
    else s_.wrap(i);
  }
  s_.build_cells(Scanner::cells_per_particle, shell());
  scanner_.rebuilt(s_);
  std::vector<double> keys(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    scan(i, -1, 0, Top2{});
    keys[i] = std::min(s_.ev[i].t_pair, s_.ev[i].t_cross);
  }
  q_.build(keys);
}

template <int D, Features F, class Scan>
inline void Engine<D, F, Scan>::look_ahead() {
  q_.prefetch(q_.ahead(3));
  const std::int32_t b = q_.ahead(2);
  if (b >= 0) __builtin_prefetch(&s_.ev[static_cast<std::uint32_t>(b)]);
  const std::int32_t c = q_.ahead(1);
  if (c >= 0) {
    const Ev& e = s_.ev[static_cast<std::uint32_t>(c)];
    __builtin_prefetch(s_.p.position(static_cast<std::uint32_t>(c)).data());
    if (e.partner >= 0 && e.t_pair <= e.t_cross) {
      __builtin_prefetch(s_.p.position(static_cast<std::uint32_t>(e.partner)).data());
      __builtin_prefetch(&s_.cnt[static_cast<std::uint32_t>(e.partner)]);
      if constexpr (lists) scanner_.prefetch_lists(static_cast<std::uint32_t>(c),
                                                   static_cast<std::uint32_t>(e.partner));
    }
  }
}

template <int D, Features F, class Scan>
template <bool Record>
inline void Engine<D, F, Scan>::collide(std::uint32_t i, std::uint32_t j) {
  if (le_.on()) [[unlikely]] {
    collide_sheared(i, j);
    return;
  }
  State<D, F>& s = s_;
  s.advance(i);
  s.advance(j);
  Vec<D> r = s.p.position(i) - s.p.position(j);
  for (int k = 0; k < D; ++k) r[k] -= s.L * std::round(r[k] / s.L);  // contact: |r_k| <= L/2
  const double rn = r.norm();
  const Vec<D> n = r / rn;
  const double wi = s.p.inv_mass(i), wj = s.p.inv_mass(j);
  const Vec<D> vi0 = s.p.velocity(i);
  [[maybe_unused]] const Vec<D> vj0 = s.p.velocity(j);
  if (alpha_ < 1.0) [[unlikely]] {
    collide_granular(i, j, wi, wj, n);
  } else {
    detail::collide_unchecked<D>(s.p.velocity(i), s.p.velocity(j), wi, wj, n);
  }
  if (s.rate != 0.0) {  // LS: separate at least as fast as the contact distance grows
    const double a = 2.0 * s.base_contact(i, j) * s.rate;
    s.p.velocity(i) += (a * wi / (wi + wj)) * n;
    s.p.velocity(j) -= (a * wj / (wi + wj)) * n;
  }
  win_.virial += (s.p.velocity(i) - vi0).dot(r) / wi;
  if constexpr (Record) {
    const Vec<D> vi1 = s.p.velocity(i), vj1 = s.p.velocity(j);
    contacts_.helfand->template collision<D>(s.now, s.id[i], s.id[j], vi0.data(), vj0.data(),
                                             vi1.data(), vj1.data(), r.data());
  }
  ++s.cnt[i];
  ++s.cnt[j];
  ++s.ncoll;
}

template <int D, Features F, class Scan>
inline void Engine<D, F, Scan>::cross(std::uint32_t i) {
  State<D, F>& s = s_;
  if constexpr (lists) {
    if (s.cells.per_side() > 1) {  // i left the sphere around its list's anchor
      s.wrap(i);
      scanner_.relist(s, i);
      predict(i);
      return;
    }
  }
  s.advance(i);
  const int k = s.ev[i].cross / 2;
  const int dir = (s.ev[i].cross & 1) ? 1 : -1;
  auto c = s.cells.coords(s.cells.cell_of(i));
  const int m = s.cells.per_side();
  const double w = s.cells.width();
  auto x = s.p.position(i);
  c[k] += dir;
  if (c[k] == m) {
    c[k] = 0, x[k] = 0.0, ++s.image[i * D + k];
    if (k == 1 && le_.on()) [[unlikely]] slide(i, c, -1);  // Lees–Edwards: the top face
  } else if (c[k] < 0) {
    c[k] = m - 1, x[k] = s.L, --s.image[i * D + k];
    if (k == 1 && le_.on()) [[unlikely]] slide(i, c, 1);
  } else {
    x[k] = (dir > 0 ? c[k] : c[k] + 1) * w;
  }
  const std::uint32_t left = s.cells.cell_of(i);
  s.cells.remove(i);
  s.cells.insert(i, s.cells.index(c));
  scanner_.left_cell(s, left);  // FilteredScan: the new cell's box follows i's scan below
  Ev& e = s.ev[i];
  // SlabScan keeps the still-valid pair events and scans only the newly adjacent slab
  const bool keep = Scanner::keeps_pairs_on_crossing && m >= 3 && e.valid(s.cnt) && !le_.on();
  if (keep) {
    Top2 top{e.t_pair - s.now, e.t_pair2 - s.now, e.partner, e.partner2};
    if (top.p2 >= 0 && s.cnt[top.p2] != e.pcount2) top.t2 = never, top.p2 = -1;
    scan(i, k, dir, top);
  } else {
    scan(i, -1, 0, Top2{});
  }
  q_.update(i, std::min(e.t_pair, e.t_cross));
}

template <int D, Features F, class Scan>
inline void Engine<D, F, Scan>::reorder() {
  State<D, F>& s = s_;
  const std::uint32_t n = static_cast<std::uint32_t>(size());
  next_reorder_ = s.ncoll + reorder_every_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> key(n);
  for (std::uint32_t i = 0; i < n; ++i) key[i] = {s.cells.morton(s.cells.cell_of(i)), i};
  std::sort(key.begin(), key.end());
  std::vector<std::uint32_t> from(n), to(n), cell(n);
  for (std::uint32_t i = 0; i < n; ++i) from[i] = key[i].second, to[key[i].second] = i;
  s.p.permute(from);
  permute_records(s.image, from, D);
  permute_records(s.cnt, from, 1);
  permute_records(s.ev, from, 1);
  permute_records(s.id, from, 1);
  if (!s.t_last.empty()) permute_records(s.t_last, from, 1);
  scanner_.permute(from);
  for (std::uint32_t i = 0; i < n; ++i) {
    Ev& e = s.ev[i];
    if (e.partner >= 0) e.partner = static_cast<std::int32_t>(to[e.partner]);
    if (e.partner2 >= 0) e.partner2 = static_cast<std::int32_t>(to[e.partner2]);
    cell[i] = s.cells.cell_of(from[i]);
    s.slot[s.id[i]] = i;
  }
  s.cells.clear();
  for (std::uint32_t i = n; i-- > 0;) s.cells.insert(i, cell[i]);  // lists in slot order
  std::vector<double> keys(n);
  for (std::uint32_t i = 0; i < n; ++i) keys[i] = std::min(s.ev[i].t_pair, s.ev[i].t_cross);
  q_.build(keys);
}

}  // namespace hypergas::edmd
