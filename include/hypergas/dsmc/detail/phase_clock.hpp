// hypergas/dsmc/detail/phase_clock.hpp -- where each thread of the block schedule spends its
// time (parallel.hpp): time-stamp counter ticks per phase, summed over blocks. A few reads
// of the counter per block of thousands of candidates (below 0.1 % of a block), so the
// schedule keeps them always; `hypergas bench -j` prints them.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace hypergas::dsmc {

/// The phases of one thread's part in a block (parallel.hpp).
enum class Phase : int {
  draw_set,     ///< the conflict set of the next block (and, first, the pairs of block 0)
  chunk,        ///< the thread's chunk: draw, conflict test, acceptance, collisions
  wait_chunk,   ///< waiting for the other threads to finish their chunks
  tail,         ///< thread 0: the deferred candidates in block order and any undoing
  wait_tail,    ///< waiting for the block's end
  count
};
inline constexpr int phase_count = static_cast<int>(Phase::count);
inline constexpr std::array<const char*, phase_count> phase_names{"draw_set", "chunk", "wait_chunk",
                                                                  "tail", "wait_tail"};

/// Ticks per phase of one thread, and the blocks and deferred candidates it saw.
struct alignas(64) PhaseTicks {  // one cache line per thread or more
  std::array<std::uint64_t, phase_count> ticks{};
  std::uint64_t blocks = 0, candidates = 0, deferred = 0;
  void add(const PhaseTicks& o) {
    for (int p = 0; p < phase_count; ++p) ticks[std::size_t(p)] += o.ticks[std::size_t(p)];
    blocks += o.blocks, candidates += o.candidates, deferred += o.deferred;
  }
};

/// The time-stamp counter (x86), else a steady clock in nanoseconds.
inline std::uint64_t ticks_now() {
#if defined(__x86_64__) || defined(__i386__)
  return __rdtsc();
#else
  return static_cast<std::uint64_t>(
      std::chrono::steady_clock::now().time_since_epoch() / std::chrono::nanoseconds(1));
#endif
}

namespace detail {

/// Stamps the end of one phase and the start of the next.
class PhaseClock {
 public:
  explicit PhaseClock(PhaseTicks& into) : into_(into), last_(ticks_now()) {}
  /// Adds the ticks since the last lap to phase p and returns them.
  std::uint64_t lap(Phase p) {
    const std::uint64_t now = ticks_now(), d = now - last_;
    into_.ticks[std::size_t(p)] += d;
    last_ = now;
    return d;
  }

 private:
  PhaseTicks& into_;
  std::uint64_t last_;
};

}  // namespace detail
}  // namespace hypergas::dsmc
