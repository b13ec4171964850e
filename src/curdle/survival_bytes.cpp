#include "curdle/survival_bytes.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace curdle {

// 16 survival bytes of one draw against the threshold's top byte: which are below, which tie.
void compare_bytes(const RandomStream::Block& r, uint32_t top, uint32_t& below, uint32_t& tie) {
#if defined(__SSE2__)
  const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(r.data()));
  const __m128i flip = _mm_set1_epi8(static_cast<char>(0x80));
  const __m128i t = _mm_set1_epi8(static_cast<char>(top ^ 0x80));
  below = static_cast<uint32_t>(_mm_movemask_epi8(_mm_cmplt_epi8(_mm_xor_si128(v, flip), t)));
  tie = static_cast<uint32_t>(
      _mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_set1_epi8(static_cast<char>(top)))));
#else
  below = tie = 0;
  for (unsigned word = 0; word < 4; ++word)
    for (unsigned q = 0; q < 4; ++q) {
      const uint32_t u = (r[word] >> (8 * q)) & 0xff;
      below |= static_cast<uint32_t>(u < top) << (4 * word + q);
      tie |= static_cast<uint32_t>(u == top) << (4 * word + q);
    }
#endif
}

// compare_bytes for draws held as four word arrays (philox_batch.h), four at a time: an SSE
// 4 x 4 transpose puts each draw's 16 bytes in one register without a trip through memory.
void compare_lanes(const uint32_t* w0, const uint32_t* w1, const uint32_t* w2, const uint32_t* w3,
                   size_t lanes, uint32_t top, uint16_t* below, uint16_t* tie) {
  size_t i = 0;
#if defined(__SSE2__)
  const __m128i flip = _mm_set1_epi8(static_cast<char>(0x80));
  const __m128i t = _mm_set1_epi8(static_cast<char>(top ^ 0x80));
  const __m128i eq = _mm_set1_epi8(static_cast<char>(top));
  for (; i + 4 <= lanes; i += 4) {
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w0 + i));
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w1 + i));
    const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w2 + i));
    const __m128i d = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w3 + i));
    const __m128i ab_lo = _mm_unpacklo_epi32(a, b), ab_hi = _mm_unpackhi_epi32(a, b);
    const __m128i cd_lo = _mm_unpacklo_epi32(c, d), cd_hi = _mm_unpackhi_epi32(c, d);
    const __m128i draw[4] = {_mm_unpacklo_epi64(ab_lo, cd_lo), _mm_unpackhi_epi64(ab_lo, cd_lo),
                             _mm_unpacklo_epi64(ab_hi, cd_hi), _mm_unpackhi_epi64(ab_hi, cd_hi)};
    for (int k = 0; k < 4; ++k) {
      below[i + k] =
          static_cast<uint16_t>(_mm_movemask_epi8(_mm_cmplt_epi8(_mm_xor_si128(draw[k], flip), t)));
      tie[i + k] = static_cast<uint16_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(draw[k], eq)));
    }
  }
#endif
  for (; i < lanes; ++i) {
    uint32_t b = 0, e = 0;
    compare_bytes(RandomStream::Block{{w0[i], w1[i], w2[i], w3[i]}}, top, b, e);
    below[i] = static_cast<uint16_t>(b);
    tie[i] = static_cast<uint16_t>(e);
  }
}

}  // namespace curdle
