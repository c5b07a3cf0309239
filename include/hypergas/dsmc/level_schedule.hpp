// hypergas/dsmc/level_schedule.hpp -- which candidates of a block can be processed at once.
//
// The sequential process takes candidates in order; candidate c depends on an earlier
// candidate only through a shared particle (two candidates on disjoint pairs commute). A
// block of candidates is cut into T contiguous chunks, one per thread. Before the block,
// thread t draws the candidates of the chunks before its own again and puts their
// particles into a set (ParticleFilter: a small table in the core's own cache; the velocity
// array is not touched). Then each thread runs through its chunk in order and defers
// candidate c when
//   - a particle of c is in the set of an earlier chunk (c may depend on that chunk), or
//   - a particle of c belongs to a candidate deferred earlier in its own chunk;
// all other candidates are processed at once, each thread in its chunk's order. Thread 0
// then takes the deferred candidates in block order.
//
// This gives the sequential result bit for bit. A processed (not deferred) candidate f of
// chunk t shares no particle with any candidate of chunks before t, nor with a deferred
// candidate before it in chunk t; the candidates of later chunks that share a particle
// with f are deferred (f's particles are in chunk t's set). So every candidate that f
// depends on is processed before f (earlier in its own chunk), and every candidate that
// depends on f after it. A
// deferred candidate finds all earlier candidates applied (free ones in the parallel phase,
// deferred ones before it in block order). Deferring is always safe; it only costs time.
//
// With N particles and chunks of C candidates, a candidate of chunk t is deferred with
// probability about 4 t C / N: blocks are kept at a few per cent of N.
//
// A GPU port can keep the same split: a kernel builds the chunk sets, a kernel processes
// the free candidates (one chunk per thread block, in order within the chunk), and the
// deferred few go in order; the draws of candidate K depend on K only
// (hypergas/counter_rng.hpp), so any schedule that respects this order gives the same gas.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hypergas::dsmc::detail {

/// A set of particle indices that may answer "yes" for a particle it does not hold, never
/// "no" for one it holds: deferring too much is safe. It is a direct-mapped table with at
/// least 8 slots per particle it will hold: a slot keeps the one particle that hashed there,
/// or a mark that two or more did (then every particle hashing there reads as held; a
/// particle not held reads as held with probability about (n / slots)^2 / 2 < 1 %). A look-up
/// is one load and a compare, with no branch to mispredict; emptying it rewrites only the
/// slots that were used.
class ParticleFilter {
 public:
  /// Empties the filter and makes room for `count` insertions at the stated load.
  void reserve(std::size_t count) {
    clear();
    std::size_t cap = 1024;
    while (cap < 8 * count) cap *= 2;
    if (slots_.size() < cap) {
      slots_.assign(cap, 0u);
      shift_ = 64;
      for (std::size_t c = cap; c > 1; c /= 2) --shift_;
    }
    grow_at_ = slots_.size() / 8;
  }
  void clear() {
    for (const std::uint32_t s : used_) slots_[s] = 0u;
    used_.clear();
    keys_.clear();
  }
  bool empty() const { return keys_.empty(); }
  void insert(std::uint32_t p) {
    if (keys_.size() >= grow_at_) [[unlikely]]
      regrow();
    keys_.push_back(p);
    place(p);
  }
  /// True if p was inserted (and, rarely, if it was not).
  bool contains(std::uint32_t p) const {
    const std::uint32_t x = slots_[home(p)];
    return x == p + 1 || x == shared;
  }

 private:
  static constexpr std::uint32_t shared = 0xffffffffu;  // two or more particles here
  std::size_t home(std::uint32_t p) const {
    return static_cast<std::size_t>((std::uint64_t(p) * 0x9e3779b97f4a7c15ULL) >> shift_);
  }
  void place(std::uint32_t p) {
    const std::size_t s = home(p);
    const std::uint32_t key = p + 1;  // 0: empty
    const std::uint32_t old = slots_[s];
    if (old == 0) {
      slots_[s] = key;
      used_.push_back(static_cast<std::uint32_t>(s));
    } else if (old != key) {
      slots_[s] = shared;
    }
  }
  void regrow() {  // more insertions than reserved: a table twice as large, filled again
    for (const std::uint32_t s : used_) slots_[s] = 0u;
    used_.clear();
    slots_.assign(std::max<std::size_t>(1024, 2 * slots_.size()), 0u);
    shift_ = 64;
    for (std::size_t c = slots_.size(); c > 1; c /= 2) --shift_;
    grow_at_ = slots_.size() / 8;
    for (const std::uint32_t p : keys_) place(p);
  }
  std::vector<std::uint32_t> slots_;
  std::vector<std::uint32_t> used_;  // slots written since the last clear
  std::vector<std::uint32_t> keys_;  // particles inserted since the last clear
  std::size_t grow_at_ = 0;
  int shift_ = 54;
};

}  // namespace hypergas::dsmc::detail
