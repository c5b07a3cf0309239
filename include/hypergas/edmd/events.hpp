// hypergas/edmd/events.hpp -- a particle's predicted events: its two earliest pair events
// and its next cell crossing (Ev), and the two earliest pair times of a scan (Top2).
//
// Each particle keeps a local clock (its position is stored at the time of its last event),
// its two earliest predicted pair events (time, partner, partner's event counter) and one
// cell-crossing time; the earliest is its key in the event queue. A pair event is valid
// only if the partner's counter is unchanged (lazy invalidation; Ev::valid, Ev::valid2);
// when the first is invalid the runner-up is used if still valid, else the particle is
// scanned again (Engine::step). Recording a scan's result is State::store, the crossing
// time State::predict_crossing (state.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "hypergas/edmd/pair_time.hpp"

namespace hypergas::edmd {

/// The predicted events of one particle (absolute times).
struct Ev {
  double t_pair = never;
  double t_cross = never;
  double t_pair2 = never;   // second-earliest pair event of the same scan (fallback)
  std::int32_t partner = -1;
  std::uint32_t pcount = 0;
  std::int32_t partner2 = -1;
  std::uint32_t pcount2 = 0;
  std::int32_t cross = 0;  // axis * 2 + (1 if upward)

  /// Whether the first (second) pair event still holds: its partner has had no collision
  /// since the scan, by the collision counters `cnt`.
  bool valid(const std::vector<std::uint32_t>& cnt) const {
    return partner >= 0 && cnt[partner] == pcount;
  }
  bool valid2(const std::vector<std::uint32_t>& cnt) const {
    return partner2 >= 0 && cnt[partner2] == pcount2;
  }
};

/// The two earliest pair times (relative) and partners found by a scan.
struct Top2 {
  double t1 = never, t2 = never;
  std::int32_t p1 = -1, p2 = -1;
  void offer(double t, std::int32_t j) {
    if (t < t2) {
      if (t < t1) {
        t2 = t1, p2 = p1;
        t1 = t, p1 = j;
      } else {
        t2 = t, p2 = j;
      }
    }
  }
};

}  // namespace hypergas::edmd
