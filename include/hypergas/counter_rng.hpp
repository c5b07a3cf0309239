// hypergas/counter_rng.hpp -- counter-based random numbers: draws that are pure functions of
// (seed, event number), so that whoever processes an event, and when, draws the same.
//
// The generator is SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014) in counter mode: word number x of a seed is
// mix64(key + x * gamma), the x-th output of the SplitMix64 sequence that starts at `key`
// (key derived from the seed). SplitMix64 passes TestU01 BigCrush; as its output is a
// bijective function of the counter, distinct counters never repeat a state. Event K (a
// DSMC candidate, numbered from 0 since the start of the run) owns the 16 consecutive words
// 16 K .. 16 K + 15; it takes its pair and acceptance uniform from the first two and its
// scattering direction from the following ones. The rare event that needs more than 16
// words (a long run of rejections) continues in a second sequence at a hashed start.
//
// SplitMix64 rather than a stronger counter-based generator such as Philox4x32-10: it is the
// cheaper of the two per word (docs/benchmarks.md, "Tried and rejected").
#pragma once

#include <cstdint>

#include "hypergas/rng.hpp"

namespace hypergas {

/// What a counter-based stream numbers, so that two uses of one seed never share words.
enum class Domain : std::uint64_t { dsmc_candidate = 1 };

/// The random words of numbered events under one seed.
class EventDraws {
 public:
  /// Words each event owns in the main sequence.
  static constexpr std::uint64_t words_per_event = 16;

  EventDraws(std::uint64_t seed, Domain domain)
      : key_(detail::mix64(seed ^ detail::mix64(static_cast<std::uint64_t>(domain)))),
        overflow_key_(detail::mix64(key_ ^ 0x6a09e667f3bcc909ULL)) {}
  /// Word w of event K: w < 16 from the main sequence, beyond from the overflow sequence.
  [[gnu::always_inline]] std::uint64_t word(std::uint64_t K, std::uint64_t w) const {
    if (w < words_per_event) [[likely]]
      return detail::mix64(key_ + (K * words_per_event + w) * gamma);
    return overflow_word(K, w);
  }

 private:
  [[gnu::noinline]] std::uint64_t overflow_word(std::uint64_t K, std::uint64_t w) const {
    return detail::mix64(overflow_key_ + detail::mix64(K) + (w - words_per_event) * gamma);
  }
  static constexpr std::uint64_t gamma = 0x9e3779b97f4a7c15ULL;
  std::uint64_t key_;
  std::uint64_t overflow_key_;
};

/// The words of one event from word `first` on. Satisfies std::uniform_random_bit_generator,
/// with uniform() and uniform_pos() like Rng, so the scattering samplers take it unchanged.
class EventStream {
 public:
  using result_type = std::uint64_t;
  EventStream(const EventDraws& d, std::uint64_t event, std::uint64_t first)
      : d_(&d), event_(event), next_(first) {}
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return ~result_type{0}; }
  result_type operator()() { return d_->word(event_, next_++); }
  double uniform() { return detail::unit_interval((*this)()); }
  double uniform_pos() { return detail::unit_interval_pos((*this)()); }

 private:
  const EventDraws* d_;
  std::uint64_t event_;
  std::uint64_t next_;
};

}  // namespace hypergas
