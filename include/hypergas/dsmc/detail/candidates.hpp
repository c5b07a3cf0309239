// hypergas/dsmc/detail/candidates.hpp -- what candidate K of a run draws: its pair (word 0),
// its acceptance uniform (word 1) and its scattering stream (words 2, 3, ...), all from the
// counter-based stream of counter_rng.hpp keyed by the seed. The draws are functions of
// (seed, K) only, so no thread schedule can change them (docs/design.md, "Counter-based
// draws").
#pragma once

#include <cstdint>

#include "hypergas/counter_rng.hpp"
#include "hypergas/rng.hpp"

namespace hypergas::dsmc::detail {

/// The draws of the numbered candidates of one run, among n particles.
class CandidateStream {
 public:
  explicit CandidateStream(std::uint64_t seed) : draws_(seed, Domain::dsmc_candidate) {}

  /// Candidate K: a uniformly chosen ordered pair of distinct particles (word 0) and its
  /// acceptance uniform (word 1).
  void draw(std::uint64_t K, std::uint32_t n, std::uint32_t& i, std::uint32_t& j,
            double& u) const {
    draw_pair(K, n, i, j);
    u = hypergas::detail::unit_interval(draws_.word(K, 1));
  }
  void draw_pair(std::uint64_t K, std::uint32_t n, std::uint32_t& i, std::uint32_t& j) const {
    const std::uint64_t r = draws_.word(K, 0);
    i = bounded32(K, static_cast<std::uint32_t>(r >> 32), n);
    j = bounded32(K, static_cast<std::uint32_t>(r), n - 1);
    j += (j >= i);
  }
  /// Candidate K's scattering words, from word 2 on.
  EventStream scattering(std::uint64_t K) const { return EventStream(draws_, K, 2); }

 private:
  /// Unbiased integer in [0, range) from 32 random bits x (Lemire's multiply-shift with
  /// rejection); on rejection (probability below range / 2^32) takes fresh words of
  /// candidate K from word 2^20 on, far from those its scattering uses.
  std::uint32_t bounded32(std::uint64_t K, std::uint32_t x, std::uint32_t range) const {
    const std::uint64_t m = std::uint64_t(x) * range;
    if (static_cast<std::uint32_t>(m) < range) [[unlikely]]
      return bounded32_slow(K, m, range);
    return static_cast<std::uint32_t>(m >> 32);
  }
  [[gnu::noinline]] std::uint32_t bounded32_slow(std::uint64_t K, std::uint64_t m,
                                                 std::uint32_t range) const {
    const std::uint32_t t = (0u - range) % range;
    EventStream more(draws_, K, std::uint64_t{1} << 20);
    while (static_cast<std::uint32_t>(m) < t)
      m = std::uint64_t(static_cast<std::uint32_t>(more() >> 32)) * range;
    return static_cast<std::uint32_t>(m >> 32);
  }

  EventDraws draws_;
};

}  // namespace hypergas::dsmc::detail
