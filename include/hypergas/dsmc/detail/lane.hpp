// hypergas/dsmc/detail/lane.hpp -- the candidate loop: a run of consecutive candidates
// through the batch pipeline (draw one batch ahead and prefetch its velocities, test a
// whole batch at once, take the accepted ones in order, re-test what shares a particle).
// With one thread this loop is the engine; with several, each thread runs its chunk of a
// block through it (parallel.hpp). docs/design.md, "Batches", explains why it is exact.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "hypergas/dsmc/detail/batch.hpp"
#include "hypergas/dsmc/detail/self_check.hpp"
#include "hypergas/dsmc/detail/state.hpp"
#include "hypergas/dsmc/level_schedule.hpp"

namespace hypergas::dsmc::detail {

/// One thread's pass over a chunk of candidates and what it leaves for the block's end.
struct Lane {
  std::uint32_t offset = 0;              // block position of the chunk's first candidate
  std::vector<std::uint32_t> deferred;   // block positions, ascending
  std::vector<std::uint32_t> saved_at;   // block positions of applied candidates, ascending
  std::vector<std::uint32_t> saved_ij;   // their pairs
  std::vector<double> saved;             // their old velocities (2 D each)
  ParticleFilter held;                   // particles of earlier chunks and of deferred candidates
  std::uint64_t collisions = 0;
  bool raised = false;                   // exact scheme: the lane stopped at a raise
  std::uint64_t raise_at = 0;            // block position of the raising candidate
  double raise_s2 = 0.0;
  tally::Tally delta;                    // threads after the first: their tally changes
  char pad[64];                          // two lanes' counters never share a cache line
};

/// Pairs drawn ahead: while a thread runs its chunk of one block, it also draws the pairs
/// of its chunk of the next block (count of them, from candidate `first` on) into `ij`, so
/// that later threads can fill their conflict sets from them (parallel.hpp). The loop is
/// bound by memory latency, and the draws fill its stalls.
struct DrawAhead {
  std::uint64_t first = 0;
  std::uint64_t count = 0;
  std::uint32_t* ij = nullptr;
};

/// Runs candidates first .. first + count - 1 (lane positions 0 .. count - 1) through
/// the batch pipeline, in order. Every candidate of the current batch is tested at once
/// (no velocity is written in between, so the loads overlap and no branch depends on
/// them); then the accepted ones are taken in order. A collision changes two velocities
/// only, so after it the later candidates of the batch that share a particle with it are
/// tested again. Each candidate is thus decided with the state at its turn, exactly as
/// one at a time.
///
/// Defer: the lane is a later chunk of a parallel block; a candidate on a particle of an
/// earlier chunk or of a candidate deferred before it (both in lane.held) is
/// skipped and listed in lane.deferred (dsmc/level_schedule.hpp). Save: the old
/// velocities of every applied candidate are kept so that the block can undo them.
/// Ahead: one pair of `ahead` is drawn with each candidate, the rest at the end; the thread
/// lanes also call the scattering out of line (State::collide).
/// Every collision is reported to `hook` (state.hpp).
/// Returns `count`, or (exact scheme) the position after the candidate that raised the
/// bound; the lane's collisions and raise are in lane.
///
/// S is the engine's State, or one lane of the lanes scheme (LaneView, kac_lanes.hpp): the
/// same loop over a window of the particles with the lane's own draws and bound.
template <bool Exact, bool Defer, bool Save, bool Ahead = false, class Hook = NoHook, class S>
[[gnu::noinline]] std::uint64_t run_lane(S& s, Lane& lane, std::uint64_t first,
                       std::uint64_t count, double G, const Hook& hook = Hook{},
                       DrawAhead ahead = {}) {
  constexpr int B = batch_size;
  constexpr int D = S::dim;
  using Model = typename S::ModelType;
  constexpr int stride = S::stride;
  const double* const v = s.p.velocity_data().data();
  std::array<Batch, 2> batch;
  // (the prefetches stay outside every branch: GCC 12 drops a prefetch behind one)
  const auto generate = [&](Batch& b, std::uint64_t at) {
    b.skip = 0;
    const bool whole = at + B <= count;
    for (int c = 0; c < B; ++c) {
      const std::uint64_t q = at + std::uint64_t(c);
      if (whole || q < count) {
        s.draw(first + q, b.i[c], b.j[c], b.u[c]);
        if constexpr (Ahead) {
          if (q < ahead.count) s.draw_pair(ahead.first + q, ahead.ij[2 * q], ahead.ij[2 * q + 1]);
        }
      } else {
        b.skip |= 1u << c;
        b.i[c] = b.j[c] = 0;
      }
      if constexpr (Defer) {
        if (((b.skip >> c) & 1u) == 0 &&
            (lane.held.contains(b.i[c]) | lane.held.contains(b.j[c]))) {
          b.skip |= 1u << c;
          lane.deferred.push_back(lane.offset + static_cast<std::uint32_t>(q));
          lane.held.insert(b.i[c]);
          lane.held.insert(b.j[c]);
        }
      }
      __builtin_prefetch(v + std::size_t(b.i[c]) * stride, 1);
      __builtin_prefetch(v + std::size_t(b.j[c]) * stride, 1);
    }
  };
  const auto test_all = [&](const Batch& b) {
    std::uint32_t mask = 0;
    for (int c = 0; c < B; ++c) mask |= std::uint32_t(test(s, b, c, G)) << c;
    return mask & ~b.skip;
  };
  generate(batch[0], 0);
  generate(batch[1], B);
  int cur = 0;
  for (std::uint64_t at = 0; at < count; at += B) {
    const Batch& b = batch[std::size_t(cur)];
    std::uint32_t mask = test_all(b);
    int pos = 0;  // next candidate of the batch
    for (;;) {
      if constexpr (S::checks) {
        if (s.self_check) [[unlikely]]
          verify_batch(s, b, pos, G, mask);
      }
      const std::uint32_t rest = mask >> pos << pos;
      if (rest == 0) break;
      const int c = std::countr_zero(rest);
      pos = c + 1;
      const std::uint32_t i = b.i[c], j = b.j[c];
      if constexpr (Save) {
        lane.saved_at.push_back(lane.offset + static_cast<std::uint32_t>(at + std::uint64_t(c)));
        lane.saved_ij.push_back(i);
        lane.saved_ij.push_back(j);
        for (int d = 0; d < D; ++d) lane.saved.push_back(v[std::size_t(i) * stride + d]);
        for (int d = 0; d < D; ++d) lane.saved.push_back(v[std::size_t(j) * stride + d]);
      }
      const double s2 = s.template collide<Ahead>(i, j, first + at + std::uint64_t(c), hook);
      ++lane.collisions;
      if constexpr (Model::needs_majorant) {
        // later candidates of the batch that share particle i or j: decided again
        for (std::uint32_t hit = (sharing(b, i, j) >> pos << pos) & ~b.skip; hit != 0;
             hit &= hit - 1) {
          const int c2 = std::countr_zero(hit);
          const std::uint32_t bit = 1u << c2;
          mask = test(s, b, c2, G) ? (mask | bit) : (mask & ~bit);
        }
        if (s.bound.exceeded_by(s2)) {
          lane.raise_s2 = std::max(lane.raise_s2, s2);
          if constexpr (Exact) {
            lane.raised = true;
            return at + std::uint64_t(c) + 1;
          }
        }
      }
    }
    generate(batch[std::size_t(cur)], at + 2 * B);
    cur = 1 - cur;
  }
  if constexpr (Ahead) {
    for (std::uint64_t q = count; q < ahead.count; ++q)
      s.draw_pair(ahead.first + q, ahead.ij[2 * q], ahead.ij[2 * q + 1]);
  }
  return count;
}

}  // namespace hypergas::dsmc::detail
