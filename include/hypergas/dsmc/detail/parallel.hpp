// hypergas/dsmc/detail/parallel.hpp -- one system on several threads: candidates in blocks,
// one contiguous chunk per thread through the candidate loop (lane.hpp), the candidates
// that may depend on an earlier chunk deferred to thread 0 (dsmc/level_schedule.hpp), and a
// raise of the bound undone past its candidate. The gas is bit for bit that of one thread
// for every thread count (docs/design.md, "One system on T threads").
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "hypergas/dsmc/detail/lane.hpp"
#include "hypergas/dsmc/detail/phase_clock.hpp"
#include "hypergas/dsmc/detail/self_check.hpp"
#include "hypergas/dsmc/detail/state.hpp"
#include "hypergas/thread_team.hpp"

namespace hypergas::dsmc::detail {

/// The thread team, its lanes and the block size (none of it state: set_threads rebuilds
/// it; without a team the one-thread loop runs).
class ParallelBlocks {
 public:
  /// `threads` (1 .. 256, checked by the caller), `block` candidates per block. Only an
  /// explicit block size starts the block schedule: on its own the exact scheme runs the
  /// one-thread loop whatever T is, because the schedule measured slower than one thread
  /// (0.50x at 1e5, 0.89x at 1e6, 0.83x at 1e7 particles in 3D on AMD EPYC;
  /// docs/benchmarks.md, "One system on T threads"). The lanes scheme is what uses T threads.
  void configure(int threads, std::uint32_t block) {
    threads_ = threads;
    block_ = block;
    if (block == 0) {
      team_.reset();
      lanes_.clear();
      profile_.clear();
      pairs_ = {};
      return;
    }
    if (!team_ || team_->size() != threads) team_ = std::make_unique<ThreadTeam>(threads);
    lanes_.assign(static_cast<std::size_t>(threads), Lane{});
    profile_.assign(static_cast<std::size_t>(threads), PhaseTicks{});
  }
  /// Per thread: the ticks of each phase of the block schedule since configure() or
  /// reset_profile() (empty without a team).
  const std::vector<PhaseTicks>& profile() const { return profile_; }
  void reset_profile() { profile_.assign(profile_.size(), PhaseTicks{}); }
  /// Candidates per block (0: no team).
  std::uint32_t block() const { return block_; }
  /// The threads asked for (set_threads); block() == 0 says that the one-thread loop runs.
  int threads() const { return threads_; }
  /// Whether an epoch of m candidates runs in blocks (at least four of them).
  bool takes(std::uint64_t m) const { return team_ && m >= 4u * block_; }

  /// Processes m candidates on the team, in blocks of block_ candidates cut into one chunk
  /// per thread. Same result as the one-thread loop, bit for bit.
  ///
  /// Per block b, two phases separated by barriers:
  ///  1. each thread runs its chunk through the batch pipeline (run_lane), deferring the
  ///     candidates that may depend on an earlier chunk, and draws the pairs of its chunk
  ///     of block b + 1 into pairs_; threads after the first keep the old velocities of
  ///     what they apply;
  ///  2. thread 0 takes the deferred candidates in block order up to the first raise of
  ///     the bound, undoes what later chunks applied after that raise and ends the epoch
  ///     there; meanwhile every other thread fills its set for block b + 1 from the pairs
  ///     the threads before it drew.
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
    const std::uint64_t blocks = (m + block_ - 1) / block_;
    std::uint64_t done = 0;
    bool stop = false;
    std::vector<double> before;  // self-check: the velocities at the start of the block
    if (s.self_check) save_velocities(s, before);
    for (auto& p : pairs_) p.resize(2 * std::size_t(block_));
    const auto size_of = [&](std::uint64_t b) {
      return static_cast<std::uint32_t>(std::min<std::uint64_t>(block_, m - b * block_));
    };
    // thread t's chunk of block b: positions [lo, hi), equal shares (docs/benchmarks.md
    // compares cuts that follow measured busy times)
    const auto share = [&](std::uint64_t b, int t) {
      const std::uint64_t nb = size_of(b);
      return std::pair<std::uint32_t, std::uint32_t>(static_cast<std::uint32_t>(nb * t / T),
                                                     static_cast<std::uint32_t>(nb * (t + 1) / T));
    };
    // where thread t draws the pairs of its chunk of block b (the last thread's chunk is
    // in no set: nothing to draw)
    const auto ahead_of = [&](std::uint64_t b, int t) {
      DrawAhead a;
      if (b >= blocks || t == T - 1) return a;
      const auto [lo, hi] = share(b, t);
      a.first = K0 + b * block_ + lo;
      a.count = hi - lo;
      a.ij = pairs_[b % 2].data() + 2 * std::size_t(lo);
      return a;
    };
    // thread t's set for block b: the particles of the chunks before its own, read from the
    // pairs those chunks' threads drew (the set is written and read by one core only)
    const auto fill_set = [&](std::uint64_t b, int t) {
      Lane& lane = lanes_[std::size_t(t)];
      const auto [lo, hi] = share(b, t);
      const std::uint32_t* ij = pairs_[b % 2].data();
      lane.held.reserve(2 * std::size_t(lo) + (hi - lo) / 8);  // and the deferred ones
      for (std::uint32_t c = 0; c < 2 * lo; ++c) lane.held.insert(ij[c]);
    };

    team.run([&](int t) {
      Lane& lane = lanes_[std::size_t(t)];
      PhaseTicks& prof = profile_[std::size_t(t)];
      PhaseClock clock(prof);
      const Hook hook = hook_of(t);
      {
        const DrawAhead a = ahead_of(0, t);
        for (std::uint64_t q = 0; q < a.count; ++q)
          s.draw_pair(a.first + q, a.ij[2 * q], a.ij[2 * q + 1]);
      }
      clock.lap(Phase::draw_set);
      team.sync();
      clock.lap(Phase::wait_tail);
      fill_set(0, t);
      clock.lap(Phase::draw_set);
      for (std::uint64_t b = 0;; ++b) {
        const std::uint32_t nb = size_of(b);
        const auto [lo, hi] = share(b, t);
        // 1. the chunk, deferring what may depend on earlier chunks, and the pairs of the
        // next block's chunk
        lane.offset = lo;
        lane.deferred.clear();
        lane.saved_at.clear();
        lane.saved_ij.clear();
        lane.saved.clear();
        lane.collisions = 0;
        lane.raise_s2 = 0.0;
        lane.raised = false;
        const std::uint64_t first_k = K0 + b * block_ + lo;
        const DrawAhead ahead = ahead_of(b + 1, t);
        const std::uint64_t ran =
            t == 0 ? run_lane<Exact, false, false, true>(s, lane, first_k, hi - lo, G, hook, ahead)
                   : run_lane<Exact, true, Exact && Model::needs_majorant, true>(
                         s, lane, first_k, hi - lo, G, hook, ahead);
        lane.raise_at = lane.raised ? lo + ran - 1 : nb;
        ++prof.blocks;
        prof.candidates += hi - lo;
        prof.deferred += lane.deferred.size();
        clock.lap(Phase::chunk);
        team.sync();
        clock.lap(Phase::wait_chunk);
        // 2. the block's end on thread 0; the sets of block b + 1 on the others
        if (t == 0) {
          bool raised = false;
          const std::uint32_t processed =
              finish_block<Exact>(s, K0 + b * block_, nb, G, raised, first);
          if (s.self_check) [[unlikely]] {
            check_block<Exact>(s, before, K0 + b * block_, processed, raised, G);
            save_velocities(s, before);
          }
          done += processed;
          stop = raised;
          clock.lap(Phase::tail);
        }
        if (b + 1 < blocks) fill_set(b + 1, t);
        clock.lap(Phase::draw_set);
        team.sync();
        clock.lap(Phase::wait_tail);
        if (stop || b + 1 == blocks) return;  // the same decision on every thread
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
  int threads_ = 1;
  std::unique_ptr<ThreadTeam> team_;
  std::array<std::vector<std::uint32_t>, 2> pairs_;  // blocks b and b + 1 (b mod 2): pairs drawn ahead
  std::vector<Lane> lanes_;
  std::vector<PhaseTicks> profile_;  // per thread, written by that thread only
};

}  // namespace hypergas::dsmc::detail
