// hypergas/edmd/calendar_queue.hpp -- an indexed calendar queue of per-particle event times
// (Brown 1988, CACM 31:10; for event-driven MD: Paul 2007, J. Comput. Phys. 221:615).
//
// One entry per particle (the earliest of its predicted events), updated in place: build,
// top, top_time, time_of, update. Time is cut into buckets of width w covering one "year"
// [base, base + B w); each bucket is an unsorted doubly linked list of particle ids, events
// beyond the year wait in an overflow list. The earliest event is the minimum of the
// current bucket (a few entries, found by a scan and cached); update unlinks and relinks in
// O(1). When the year is used up, the calendar is rebuilt from all entries with a new base
// (the earliest time) and a new width: w = 4 <t - t_min> / N, so that a few entries share a
// bucket near the front and a year spans ~4 mean event horizons (the overflow is the tail
// beyond that). The rebuild is O(N) work once per ~4N events. The factor 4 and the choice
// of this queue over an indexed binary heap (O(neighbours + log N) per EDMD event instead
// of O(neighbours)) are measured in docs/benchmarks.md.
//
// Event times handed in are never earlier than the current top (EDMD schedules events at or
// after `now`); a time that rounds into an earlier bucket is filed in the current one.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hypergas::edmd {

/// Calendar queue over particle ids 0..n-1 keyed by event time.
class CalendarQueue {
 public:
  /// Builds the calendar from `times[i]` for every particle i (O(n)).
  void build(const std::vector<double>& times) {
    node_.assign(times.size(), Node{});
    for (std::size_t i = 0; i < times.size(); ++i) node_[i].t = times[i];
    rebuild();
  }
  bool empty() const { return node_.empty(); }
  std::size_t size() const { return node_.size(); }
  /// Particle with the earliest event, and that time.
  std::uint32_t top() {
    settle();
    return static_cast<std::uint32_t>(min_);
  }
  double top_time() {
    settle();
    return node_[static_cast<std::uint32_t>(min_)].t;
  }
  double time_of(std::uint32_t id) const { return node_[id].t; }
  /// Sets the event time of particle `id`.
  void update(std::uint32_t id, double t) {
    unlink(id);
    if (static_cast<std::int32_t>(id) == min_) min_ = none;
    node_[id].t = t;
    link(id);
  }
  /// First entry of the bucket k after the current one (or -1): an event due soon, for
  /// the engine to prefetch its data while it handles the current one.
  std::int32_t ahead(std::uint32_t k) const {
    const std::uint32_t b = cur_ + k;
    return b < nb_ ? head_[b] : none;
  }
  /// Asks the processor for entry id (its time and links).
  void prefetch(std::int32_t id) const {
    if (id != none) __builtin_prefetch(&node_[static_cast<std::uint32_t>(id)]);
  }
  /// Saves or restores the whole calendar, links included (hypergas/checkpoint.hpp): the
  /// order within a bucket decides between equal times, so a rebuilt calendar could pop
  /// a tie in another order than the saved one.
  template <class Archive>
  void io(Archive& a) {
    a.tag("calendar");
    a(node_, head_, nb_, cur_, min_, base_, inv_w_);
  }
  /// Bytes per particle (an entry and one bucket head per particle).
  static constexpr double bytes_per_particle() {
    return sizeof(Node) + sizeof(std::int32_t);
  }

 private:
  static constexpr std::int32_t none = -1;
  /// One entry: its time and links together (16 bytes, four to a cache line), so that
  /// unlinking, relinking and scanning a bucket touch one line per entry, not one per
  /// array. An entry's bucket is not stored: bucket_for(t) gives it again (an entry's
  /// bucket is never before cur_, which stops at the first non-empty bucket, and base_ and
  /// the width change only when rebuild() relinks every entry).
  struct Node {
    double t = 0.0;
    std::int32_t next = none, prev = none;
  };

  std::uint32_t bucket_for(double t) const {
    const double x = (t - base_) * inv_w_;
    if (!(x < static_cast<double>(nb_))) return nb_;  // overflow (also +inf)
    return std::max(cur_, x > 0.0 ? static_cast<std::uint32_t>(x) : 0u);
  }
  void link(std::uint32_t id) {
    Node& e = node_[id];
    const std::uint32_t b = bucket_for(e.t);
    const std::int32_t h = head_[b];
    e.next = h;
    e.prev = none;
    if (h != none) node_[static_cast<std::uint32_t>(h)].prev = static_cast<std::int32_t>(id);
    head_[b] = static_cast<std::int32_t>(id);
    // A cached minimum stays the minimum unless this entry is earlier.
    if (min_ != none && e.t < node_[static_cast<std::uint32_t>(min_)].t)
      min_ = static_cast<std::int32_t>(id);
  }
  void unlink(std::uint32_t id) {
    const Node& e = node_[id];
    const std::int32_t p = e.prev, nx = e.next;
    if (p != none) node_[static_cast<std::uint32_t>(p)].next = nx;
    else head_[bucket_for(e.t)] = nx;
    if (nx != none) node_[static_cast<std::uint32_t>(nx)].prev = p;
  }
  /// Makes min_ the earliest entry: scans the current bucket, advancing (and starting a new
  /// year) while it is empty.
  void settle() {
    while (min_ == none) {
      std::int32_t k = head_[cur_];
      if (k == none) {
        if (++cur_ == nb_) rebuild();
        continue;
      }
      min_ = k;
      double tmin = node_[static_cast<std::uint32_t>(k)].t;
      for (k = node_[static_cast<std::uint32_t>(k)].next; k != none;
           k = node_[static_cast<std::uint32_t>(k)].next)
        if (node_[static_cast<std::uint32_t>(k)].t < tmin)
          min_ = k, tmin = node_[static_cast<std::uint32_t>(k)].t;
    }
  }
  /// New year: base = earliest time, width from the mean lead of the finite times.
  void rebuild() {
    const std::size_t n = node_.size();
    double lo = INFINITY, sum = 0.0;
    std::size_t finite = 0;
    for (const Node& e : node_)
      if (std::isfinite(e.t)) lo = std::min(lo, e.t);
    for (const Node& e : node_)
      if (std::isfinite(e.t)) sum += e.t - lo, ++finite;
    nb_ = static_cast<std::uint32_t>(std::max<std::size_t>(n, 1));
    const double mean = finite ? sum / static_cast<double>(finite) : 0.0;
    double w = 4.0 * mean / static_cast<double>(nb_);
    if (!(w > 0.0) || !std::isfinite(w)) w = 1.0;
    base_ = std::isfinite(lo) ? lo : 0.0;
    inv_w_ = 1.0 / w;
    cur_ = 0;
    min_ = none;
    head_.assign(nb_ + 1, none);
    for (std::uint32_t i = 0; i < n; ++i) link(i);
    if (!std::isfinite(lo) && n > 0) min_ = static_cast<std::int32_t>(head_[nb_]);  // all never
  }

  std::vector<Node> node_;
  std::vector<std::int32_t> head_;  // nb_ buckets + the overflow list
  std::uint32_t nb_ = 0, cur_ = 0;
  std::int32_t min_ = none;
  double base_ = 0.0, inv_w_ = 1.0;
};

}  // namespace hypergas::edmd
