// hypergas/dsmc/detail/batch.hpp -- a batch of 16 consecutive candidates of the candidate
// loop (lane.hpp): their pairs and acceptance uniforms, tested all at once, and the mask of
// the later candidates that share a particle with a collision (those are tested again).
#pragma once

#include <array>
#include <cstdint>

#include "hypergas/dsmc/detail/state.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hypergas::dsmc::detail {

/// Candidates per batch: the next batch is drawn and its velocities prefetched while the
/// current one is processed (prefetch distance 16..32).
inline constexpr int batch_size = 16;

struct Batch {
  std::array<std::uint32_t, batch_size> i{}, j{};
  std::array<double, batch_size> u{};  // acceptance uniforms (models with a majorant)
  std::uint32_t skip = 0;     // bit c: candidate c is not processed here (deferred or past the end)
};

/// Whether candidate c of batch b is accepted with the velocities of now and bound G.
template <class S>
[[gnu::always_inline]] inline bool test(const S& s, const Batch& b, int c, double G) {
  return s.accepts(b.i[c], b.j[c], b.u[c], G);
}

/// Bit c set: candidate c of batch b involves particle i or j (SSE2 compares four
/// candidates at a time, which is every x86-64; a plain loop elsewhere).
inline std::uint32_t sharing(const Batch& b, std::uint32_t i, std::uint32_t j) {
#if defined(__SSE2__)
  const __m128i si = _mm_set1_epi32(static_cast<int>(i));
  const __m128i sj = _mm_set1_epi32(static_cast<int>(j));
  std::uint32_t m = 0;
  for (int q = 0; q < batch_size; q += 4) {
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b.i.data() + q));
    const __m128i e = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b.j.data() + q));
    const __m128i in_a = _mm_or_si128(_mm_cmpeq_epi32(a, si), _mm_cmpeq_epi32(a, sj));
    const __m128i in_e = _mm_or_si128(_mm_cmpeq_epi32(e, si), _mm_cmpeq_epi32(e, sj));
    const __m128i hit = _mm_or_si128(in_a, in_e);
    m |= static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(hit))) << q;
  }
  return m;
#else
  std::uint32_t m = 0;
  for (int c = 0; c < batch_size; ++c)
    m |= std::uint32_t((b.i[c] == i) | (b.i[c] == j) | (b.j[c] == i) | (b.j[c] == j)) << c;
  return m;
#endif
}

}  // namespace hypergas::dsmc::detail
