// hypergas/edmd/path_box.hpp -- the 16-byte box bounding a particle's path until its next
// cell crossing, as kept by the filtered scan (scan_filtered.hpp), and its two operations:
// the gap test against a scanner's box (near) and the union of two boxes (unite).
//
// Box bounding a particle's straight path from its last scan to its next cell crossing
// on a grid of box_levels levels per unit length, rounded outward, kept modulo 256 (a
// byte per bound). Every event that changes a path (collision, crossing, stale rescan)
// rescans the particle and rewrites its box. A collision at t* found by the later scanner i
// of a pair (the horizon scan's argument, scan_horizon.hpp) has the partner j at t* on the
// path j had at its last scan, so inside j's box: a j whose box is farther than a contact
// distance from i's box is not a partner to find now, and is skipped.
// Lanes 2k, 2k+1 hold lo_k and -hi_k; a scanner's `probe` holds hi_k and -lo_k, so
// lane-wise differences are lo_j - hi_i and lo_i - hi_j: the per-axis gaps when positive
// (never both). The grid has 256 p levels per box side L, p = floor(m / 5) for m >= 5
// cells per side (so 256 levels span 5 to 9 cells: a level is at most 9/256 of a cell
// width, 0.024 sigma in the 6D benchmark), and modulo 256 it is periodic in L. Boxes of
// a scan lie in neighbouring cells, less than 2 cells = 2 * 256 p / m <= 102.4 levels
// (+2 rounding) apart, so the differences taken as signed bytes are the true ones.
#pragma once

#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hypergas::edmd {

/// A path box (see the file comment): lanes 2k, 2k+1 hold lo_k and -hi_k in grid levels.
struct alignas(16) PBox {
  static constexpr int lanes = 16;
  std::uint8_t v[lanes];
  /// Whether the squared gap sum of boxes b and probe is at most `bound` (levels^2).
  static bool near(const PBox& b, const PBox& probe, std::int32_t bound) {
#if defined(__SSE2__)
    const __m128i zero = _mm_setzero_si128();
    const __m128i d = _mm_sub_epi8(_mm_load_si128(reinterpret_cast<const __m128i*>(b.v)),
                                   _mm_load_si128(reinterpret_cast<const __m128i*>(probe.v)));
    // signed bytes to 16-bit lanes, negative gaps to 0
    const __m128i lo = _mm_max_epi16(_mm_srai_epi16(_mm_unpacklo_epi8(d, d), 8), zero);
    const __m128i hi = _mm_max_epi16(_mm_srai_epi16(_mm_unpackhi_epi8(d, d), 8), zero);
    __m128i acc = _mm_add_epi32(_mm_madd_epi16(lo, lo), _mm_madd_epi16(hi, hi));
    acc = _mm_add_epi32(acc, _mm_shuffle_epi32(acc, 0x4E));
    acc = _mm_add_epi32(acc, _mm_shuffle_epi32(acc, 0xB1));
    return _mm_cvtsi128_si32(acc) <= bound;
#else
    std::int32_t s = 0;
    for (int l = 0; l < lanes; ++l) {
      const std::int32_t e =
          static_cast<std::int8_t>(static_cast<std::uint8_t>(b.v[l] - probe.v[l]));
      const std::int32_t g = e > 0 ? e : 0;
      s += g * g;
    }
    return s <= bound;
#endif
  }
  /// Union of two path boxes of one cell (lane-wise the lower bound, and the lower -hi):
  /// the lanes of a cell's boxes lie within 128 levels of each other (see the file
  /// comment), so the smaller of two is the one whose signed byte difference to the other
  /// is negative.
  static PBox unite(const PBox& a, const PBox& b) {
#if defined(__SSE2__)
    const __m128i x = _mm_load_si128(reinterpret_cast<const __m128i*>(a.v));
    const __m128i y = _mm_load_si128(reinterpret_cast<const __m128i*>(b.v));
    const __m128i take = _mm_cmpgt_epi8(_mm_setzero_si128(), _mm_sub_epi8(y, x));
    PBox u;
    _mm_store_si128(reinterpret_cast<__m128i*>(u.v),
                    _mm_xor_si128(x, _mm_and_si128(_mm_xor_si128(x, y), take)));
    return u;
#else
    PBox u;
    for (int l = 0; l < PBox::lanes; ++l) {
      const auto d = static_cast<std::int8_t>(static_cast<std::uint8_t>(b.v[l] - a.v[l]));
      u.v[l] = d < 0 ? b.v[l] : a.v[l];
    }
    return u;
#endif
  }
};

}  // namespace hypergas::edmd
