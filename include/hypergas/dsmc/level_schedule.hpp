// hypergas/dsmc/level_schedule.hpp -- which candidates of a block can be processed at once.
//
// The sequential process takes candidates in order; candidate c depends on an earlier
// candidate only through a shared particle (two candidates on disjoint pairs commute). A
// block of candidates is cut into T contiguous chunks, one per thread. While running its
// chunk of the block before, each thread draws the pairs of its chunk of this block into a
// shared array; thread t then puts the particles of the chunks before its own into a set
// (ParticleFilter: a bit table in the core's own cache; the velocity array is not touched).
// Then each thread runs through its chunk in order and defers candidate c when
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
/// "no" for one it holds: deferring too much is safe. It is a table of bits, at least
/// `bits_per_key` per particle it is reserved for, and a particle sets (and reads) the one
/// bit its hash picks: a particle not held reads as held with probability about
/// keys / bits (below 1 % at the reserved load; more insertions than reserved only raise
/// that probability). An insertion is one load, an or and a store, a look-up one load and a
/// test, with no branch; emptying it clears the table's used part, one word per 64 bits.
/// docs/benchmarks.md ("One system on T threads") compares it with the table of particle
/// indices it replaced.
class ParticleFilter {
 public:
  static constexpr std::size_t bits_per_key = 128;

  /// Empties the filter and sizes it for `count` insertions.
  void reserve(std::size_t count) {
    std::size_t bits = 4096;
    while (bits < bits_per_key * count) bits *= 2;
    words_ = bits / 64;
    if (table_.size() < words_) table_.assign(words_, 0u);
    else std::fill_n(table_.begin(), words_, std::uint64_t{0});
    shift_ = 64;
    for (std::size_t c = bits; c > 1; c /= 2) --shift_;
  }
  void insert(std::uint32_t p) {
    const std::uint64_t h = hash(p);
    table_[h >> 6] |= std::uint64_t{1} << (h & 63);
  }
  /// True if p was inserted (and, rarely, if it was not).
  bool contains(std::uint32_t p) const {
    const std::uint64_t h = hash(p);
    return (table_[h >> 6] >> (h & 63)) & 1u;
  }

 private:
  std::uint64_t hash(std::uint32_t p) const {
    return (std::uint64_t(p) * 0x9e3779b97f4a7c15ULL) >> shift_;
  }
  std::vector<std::uint64_t> table_;
  std::size_t words_ = 0;
  int shift_ = 52;
};

}  // namespace hypergas::dsmc::detail
