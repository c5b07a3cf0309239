// hypergas/dsmc/detail/parallel.hpp -- one system on several threads: candidates in blocks,
// one contiguous chunk per thread through the candidate loop (lane.hpp), the candidates
// that may depend on an earlier chunk deferred to thread 0 (dsmc/level_schedule.hpp), and a
// raise of the bound undone past its candidate. The gas is bit for bit that of one thread
// for every thread count (docs/design.md, "One system on T threads").
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "hypergas/dsmc/detail/lane.hpp"
#include "hypergas/dsmc/detail/self_check.hpp"
#include "hypergas/dsmc/detail/state.hpp"
#include "hypergas/thread_team.hpp"

namespace hypergas::dsmc::detail {

/// The thread team, its lanes and the block size (none of it state: set_threads rebuilds
/// it; without a team the one-thread loop runs).
class ParallelBlocks {
 public:
  /// `threads` (1 .. 256, checked by the caller) on n particles; `block` candidates per
  /// block (0: chosen from n). Below about 20000 particles, and on one thread, no team
  /// is kept unless a block size is given.
  void configure(int threads, std::uint32_t block, std::uint32_t n) {
    const std::uint32_t auto_block = std::clamp<std::uint32_t>(n / 64, 2048, 65536);
    const bool parallel = block > 0 || (threads > 1 && n >= 20000);
    block_ = parallel ? (block > 0 ? block : auto_block) : 0;
    if (!parallel) {
      team_.reset();
      lanes_.clear();
      return;
    }
    if (!team_ || team_->size() != threads) team_ = std::make_unique<ThreadTeam>(threads);
    lanes_.assign(static_cast<std::size_t>(threads), Lane{});
  }
  /// Threads that process one candidate block together (1: the one-thread loop).
  int threads() const { return team_ ? team_->size() : 1; }
  /// Whether an epoch of m candidates runs in blocks (at least four of them).
  bool takes(std::uint64_t m) const { return team_ && m >= 4u * block_; }

  /// Processes m candidates on the team, in blocks of block_ candidates cut into one chunk
  /// per thread. Same result as the one-thread loop, bit for bit.
  ///
  /// Per block b, two phases separated by barriers:
  ///  1. each thread runs its chunk through the batch pipeline (run_lane), deferring the
  ///     candidates that may depend on an earlier chunk; threads after the first keep the
  ///     old velocities of what they apply;
  ///  2. thread 0 takes the deferred candidates in block order up to the first raise of
  ///     the bound, undoes what later chunks applied after that raise and ends the epoch
  ///     there; meanwhile every thread draws its chunk of block b + 1 and fills its set.
  ///
  /// With a tally (State::tally), thread 0 applies its collisions, the deferred ones and
  /// the undoing to it, the other threads to their lane's delta, and the deltas are merged
  /// at the end: integer sums, the same for every thread count.
  template <bool Exact, int D, class Model, Features F>
  std::uint64_t process(State<D, Model, F>& s, std::uint64_t m) {
    if (!s.tally.tally) return process<Exact>(s, m, NoHook{}, [](int) { return NoHook{}; });
    tally::Tally& main = *s.tally.tally;
    for (std::size_t t = 1; t < lanes_.size(); ++t)
      if (!(lanes_[t].delta.layout() == main.layout())) lanes_[t].delta = tally::Tally(main.layout());
    const TallyHook first{&main};
    const std::uint64_t done = process<Exact>(s, m, first, [&](int t) {
      TallyHook h = first;
      if (t > 0) h.t = &lanes_[std::size_t(t)].delta;
      return h;
    });
    for (std::size_t t = 1; t < lanes_.size(); ++t) {
      main.merge(lanes_[t].delta);
      lanes_[t].delta.clear();
    }
    return done;
  }

 private:
  /// process() with the hook of thread 0 (`first`) and hook_of(t) for thread t.
  template <bool Exact, int D, class Model, Features F, class Hook, class HookOf>
  std::uint64_t process(State<D, Model, F>& s, std::uint64_t m, const Hook& first,
                        HookOf&& hook_of) {
    ThreadTeam& team = *team_;
    const int T = team.size();
    const double G = s.bound.bound();
    const std::uint64_t K0 = s.candidates;
    std::uint64_t done = 0;
    bool stop = false;
    std::vector<double> before;  // self-check: the velocities at the start of the block
    if (s.self_check) save_velocities(s, before);
    const auto block_after = [&](std::uint64_t start) {
      return static_cast<std::uint32_t>(std::min<std::uint64_t>(block_, m - start));
    };
    const auto share = [T](std::uint32_t nb, int t) {
      return std::pair<std::uint32_t, std::uint32_t>(
          static_cast<std::uint32_t>(std::uint64_t(nb) * t / T),
          static_cast<std::uint32_t>(std::uint64_t(nb) * (t + 1) / T));
    };
    // thread t's set: the particles of the chunks before its own (drawn again here, so that
    // the set is written and read by one core only)
    const auto prepare = [&](std::uint64_t start, std::uint32_t nb, int t) {
      Lane& lane = lanes_[std::size_t(t)];
      const std::uint32_t lo = share(nb, t).first;
      lane.earlier.reserve(2 * std::size_t(lo));
      for (std::uint32_t c = 0; c < lo; ++c) {
        std::uint32_t i, j;
        s.draw_pair(K0 + start + c, i, j);
        lane.earlier.insert(i);
        lane.earlier.insert(j);
      }
    };

    team.run([&](int t) {
      Lane& lane = lanes_[std::size_t(t)];
      const Hook hook = hook_of(t);
      std::uint64_t start = 0;
      std::uint32_t nb = block_after(0);
      prepare(0, nb, t);
      team.sync();
      for (;;) {
        const auto [lo, hi] = share(nb, t);
        // 1. the chunk, deferring what may depend on earlier chunks
        lane.offset = lo;
        lane.deferred.clear();
        lane.saved_at.clear();
        lane.saved_ij.clear();
        lane.saved.clear();
        lane.held.reserve(std::size_t(hi - lo) / 8);
        lane.collisions = 0;
        lane.raise_s2 = 0.0;
        lane.raised = false;
        const std::uint64_t first_k = K0 + start + lo;
        const std::uint64_t ran =
            t == 0 ? run_lane<Exact, false, false>(s, lane, first_k, hi - lo, G, hook)
                   : run_lane<Exact, true, Exact && Model::needs_majorant>(s, lane, first_k,
                                                                          hi - lo, G, hook);
        lane.raise_at = lane.raised ? lo + ran - 1 : nb;
        team.sync();
        // 2. the block's end on thread 0; the next block's sets on all
        const std::uint64_t next = start + nb;
        const std::uint32_t nn = next < m ? block_after(next) : 0;
        if (t == 0) {
          bool raised = false;
          const std::uint32_t processed =
              finish_block<Exact>(s, K0 + start, nb, G, raised, first);
          if (s.self_check) [[unlikely]] {
            check_block<Exact>(s, before, K0 + start, processed, raised, G);
            save_velocities(s, before);
          }
          done += processed;
          stop = raised;
        }
        if (nn > 0) prepare(next, nn, t);
        team.sync();
        if (stop || nn == 0) return;  // the same decision on every thread
        start = next;
        nb = nn;
      }
    });
    return done;
  }

  /// Phase 2 of a block on thread 0: the deferred candidates in block order up to the
  /// first raise (exact scheme), the undoing of what later chunks applied after it, the
  /// counters. Returns the number of candidates the block processed (up to and including
  /// the raising one); `raised` tells whether the epoch ends there.
  template <bool Exact, int D, class Model, Features F, class Hook>
  std::uint32_t finish_block(State<D, Model, F>& s, std::uint64_t base, std::uint32_t nb,
                             double G, bool& raised, const Hook& hook) {
    raised = false;
    std::uint32_t stop_at = nb;  // block position of the first raise
    double stop_s2 = 0.0, ntc_raise = 0.0;
    std::uint64_t coll = 0;
    for (const Lane& w : lanes_) {
      if (w.raise_at < stop_at) stop_at = static_cast<std::uint32_t>(w.raise_at), stop_s2 = w.raise_s2;
      coll += w.collisions;
      ntc_raise = std::max(ntc_raise, w.raise_s2);
    }
    bool end = false;
    for (const Lane& w : lanes_) {
      for (const std::uint32_t c : w.deferred) {
        if (c >= stop_at) {
          end = true;
          break;
        }
        std::uint32_t i, j;
        double u;
        s.draw(base + c, i, j, u);
        if (!s.accepts(i, j, u, G)) continue;
        const double s2 = s.collide(i, j, base + c, hook);
        ++coll;
        if constexpr (Model::needs_majorant) {
          if (s.bound.exceeded_by(s2)) {
            if constexpr (Exact) {
              stop_at = c, stop_s2 = s2;
              end = true;
              break;
            } else {
              ntc_raise = std::max(ntc_raise, s2);
            }
          }
        }
      }
      if (end) break;
    }
    if constexpr (Exact && Model::needs_majorant) {
      if (stop_at < nb) {
        // undo, newest first, what chunks after the raise applied (their particles are
        // touched by no other chunk and by no applied deferred candidate)
        constexpr int stride = State<D, Model, F>::stride;
        double* v = s.p.velocity_data().data();
        for (const Lane& w : lanes_)
          for (std::size_t a = w.saved_at.size(); a-- > 0;) {
            if (w.saved_at[a] <= stop_at) break;
            const std::uint32_t i = w.saved_ij[2 * a], j = w.saved_ij[2 * a + 1];
            const double* o = w.saved.data() + a * 2 * D;
            if constexpr (Hook::active)
              hook.collided(s.p, i, j, v + std::size_t(i) * stride, v + std::size_t(j) * stride,
                            o, o + D);
            for (int d = 0; d < D; ++d) {
              v[std::size_t(i) * stride + d] = o[d];
              v[std::size_t(j) * stride + d] = o[D + d];
            }
            --coll;
          }
        s.raise_to = std::max(s.raise_to, stop_s2);
        raised = true;
      }
    } else if constexpr (Model::needs_majorant) {
      s.raise_to = std::max(s.raise_to, ntc_raise);
    }
    s.collisions += coll;
    return raised ? stop_at + 1 : nb;
  }

  std::uint32_t block_ = 0;
  std::unique_ptr<ThreadTeam> team_;
  std::vector<Lane> lanes_;
};

}  // namespace hypergas::dsmc::detail
