// hypergas/edmd/event_queue.hpp -- an indexed binary min-heap of per-particle event times.
//
// Each particle has exactly one entry (the earliest of its predicted events); the engine
// updates that entry's time in place (decrease- or increase-key, O(log N)) instead of pushing
// new entries, so the heap never holds stale copies and has a fixed size of 16 bytes per
// particle plus a 4-byte position index. Invalid pair events (a partner that has moved on)
// are detected lazily when they reach the top, by per-particle event counters held by the
// engine. Entries store the key next to the id so that sifting touches one array.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hypergas::edmd {

/// Min-heap over particle ids 0..n-1 keyed by event time (any time unit).
class EventQueue {
 public:
  /// Builds the heap from `times[i]` for every particle i (O(n)).
  void build(const std::vector<double>& times) {
    const auto n = static_cast<std::uint32_t>(times.size());
    heap_.resize(n);
    pos_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) heap_[i] = {times[i], i};
    for (std::uint32_t i = 0; i < n; ++i) pos_[i] = i;
    for (std::size_t k = n / 2; k-- > 0;) sift_down(k);
  }
  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }
  /// Particle with the earliest event, and that time.
  std::uint32_t top() const { return heap_[0].id; }
  double top_time() const { return heap_[0].t; }
  double time_of(std::uint32_t id) const { return heap_[pos_[id]].t; }
  /// Sets the event time of particle `id` and restores the heap order.
  void update(std::uint32_t id, double t) {
    const std::size_t k = pos_[id];
    const double old = heap_[k].t;
    heap_[k].t = t;
    if (t < old) sift_up(k);
    else sift_down(k);
  }
  /// Bytes per particle (heap entry and position index).
  static constexpr double bytes_per_particle() { return sizeof(Entry) + sizeof(std::uint32_t); }

 private:
  struct Entry {
    double t;
    std::uint32_t id;
  };
  void sift_up(std::size_t k) {
    const Entry e = heap_[k];
    while (k > 0) {
      const std::size_t p = (k - 1) / 2;
      if (!(e.t < heap_[p].t)) break;
      heap_[k] = heap_[p];
      pos_[heap_[k].id] = static_cast<std::uint32_t>(k);
      k = p;
    }
    heap_[k] = e;
    pos_[e.id] = static_cast<std::uint32_t>(k);
  }
  void sift_down(std::size_t k) {
    const std::size_t n = heap_.size();
    const Entry e = heap_[k];
    for (;;) {
      std::size_t c = 2 * k + 1;
      if (c >= n) break;
      if (c + 1 < n && heap_[c + 1].t < heap_[c].t) ++c;
      if (!(heap_[c].t < e.t)) break;
      heap_[k] = heap_[c];
      pos_[heap_[k].id] = static_cast<std::uint32_t>(k);
      k = c;
    }
    heap_[k] = e;
    pos_[e.id] = static_cast<std::uint32_t>(k);
  }
  std::vector<Entry> heap_;
  std::vector<std::uint32_t> pos_;
};

}  // namespace hypergas::edmd
