// hypergas/rng.hpp -- fast, seedable, splittable random streams.
//
// The generator is O'Neill's PCG64 (pcg-cpp, "PCG: A family of simple fast space-efficient
// statistically good algorithms for random number generation", HMC-CS-2014-0905): a 128-bit
// LCG with an XSL-RR output permutation and 2^127 selectable streams. `Rng{seed, stream}`
// is fully reproducible; `split(k)` derives an independent child stream deterministically,
// so replicas and threads get streams that do not depend on scheduling.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include <pcg_random.hpp>

namespace hypergas {

namespace detail {
/// SplitMix64 finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mixer used to turn
/// (seed, k) into well-separated seeds and stream selectors.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
/// Uniform double in [0, 1) from the top 53 bits of a random word.
constexpr double unit_interval(std::uint64_t w) { return static_cast<double>(w >> 11) * 0x1.0p-53; }
/// Uniform double in (0, 1] from the top 53 bits of a random word: safe for log().
constexpr double unit_interval_pos(std::uint64_t w) {
  return static_cast<double>((w >> 11) + 1) * 0x1.0p-53;
}
}  // namespace detail

/// A random stream. Satisfies std::uniform_random_bit_generator.
class Rng {
 public:
  using result_type = std::uint64_t;

  /// Stream `stream` of seed `seed`: different (seed, stream) pairs give independent streams.
  explicit Rng(std::uint64_t seed = 1, std::uint64_t stream = 0)
      : seed_(seed), stream_(stream), engine_(detail::mix64(seed), detail::mix64(~stream)) {}

  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
  result_type operator()() { return engine_(); }

  /// An independent child stream, a pure function of (seed, stream, k).
  Rng split(std::uint64_t k) const {
    return Rng(detail::mix64(seed_ ^ detail::mix64(k + 0x51ed270b27a4f3c5ULL)),
               detail::mix64(stream_ + 0x2545f4914f6cdd1dULL * (k + 1)));
  }

  /// Uniform double in [0, 1), 53 random bits.
  double uniform() { return detail::unit_interval(engine_()); }
  /// Uniform double in (0, 1]: safe for log().
  double uniform_pos() { return detail::unit_interval_pos(engine_()); }

  /// Uniform integer in [0, n), unbiased (Lemire 2019, "Fast random integer generation in
  /// an interval", ACM TOMACS 29:3). Precondition n > 0.
  std::uint64_t below(std::uint64_t n) {
    __extension__ using u128 = unsigned __int128;
    u128 m = static_cast<u128>(engine_()) * n;
    auto lo = static_cast<std::uint64_t>(m);
    if (lo < n) {
      const std::uint64_t threshold = (0 - n) % n;
      while (lo < threshold) {
        m = static_cast<u128>(engine_()) * n;
        lo = static_cast<std::uint64_t>(m);
      }
    }
    return static_cast<std::uint64_t>(m >> 64);
  }

  /// Standard normal deviate (Marsaglia polar method; the second value is cached).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u, v, s;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double f = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * f;
    has_spare_ = true;
    return u * f;
  }

  /// Exponential deviate with mean 1.
  double exponential() { return -std::log(uniform_pos()); }

  std::uint64_t seed() const { return seed_; }
  std::uint64_t stream() const { return stream_; }

 private:
  std::uint64_t seed_;
  std::uint64_t stream_;
  pcg64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace hypergas
