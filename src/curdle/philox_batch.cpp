#include "curdle/philox_batch.h"

#include <Random123/philox.h>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace curdle {
namespace {

void philox_scalar(uint32_t* w0, uint32_t* w1, uint32_t* w2, uint32_t* w3, size_t n, uint32_t key0,
                   uint32_t key1) {
  const r123::Philox4x32 philox;
  const r123::Philox4x32::key_type key{{key0, key1}};
  for (size_t i = 0; i < n; ++i) {
    const auto r = philox(r123::Philox4x32::ctr_type{{w0[i], w1[i], w2[i], w3[i]}}, key);
    w0[i] = r[0], w1[i] = r[1], w2[i] = r[2], w3[i] = r[3];
  }
}

#if defined(__x86_64__)
// The multipliers and Weyl constants are Philox4x32's (Random123 philox.h).
// High and low 32 bits of the eight 32 x 32-bit products a * m.
__attribute__((target("avx2"))) inline void mulhilo8(__m256i a, __m256i m, __m256i& hi,
                                                     __m256i& lo) {
  const __m256i even = _mm256_mul_epu32(a, m);
  const __m256i odd = _mm256_mul_epu32(_mm256_srli_epi64(a, 32), m);
  hi = _mm256_blend_epi32(_mm256_srli_epi64(even, 32), odd, 0xAA);
  lo = _mm256_blend_epi32(even, _mm256_slli_epi64(odd, 32), 0xAA);
}

__attribute__((target("avx2"))) inline void philox8(__m256i& a, __m256i& b, __m256i& c, __m256i& d,
                                                    uint32_t key0, uint32_t key1);

__attribute__((target("avx2"))) void philox_avx2(uint32_t* w0, uint32_t* w1, uint32_t* w2,
                                                 uint32_t* w3, size_t n, uint32_t key0,
                                                 uint32_t key1) {
  size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    __m256i a = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(w0 + i));
    __m256i b = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(w1 + i));
    __m256i c = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(w2 + i));
    __m256i d = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(w3 + i));
    philox8(a, b, c, d, key0, key1);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(w0 + i), a);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(w1 + i), b);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(w2 + i), c);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(w3 + i), d);
  }
  philox_scalar(w0 + i, w1 + i, w2 + i, w3 + i, n - i, key0, key1);
}

__attribute__((target("avx2"))) inline void philox8(__m256i& a, __m256i& b, __m256i& c, __m256i& d,
                                                    uint32_t key0, uint32_t key1) {
  const __m256i m0 = _mm256_set1_epi32(static_cast<int>(0xD2511F53u));
  const __m256i m1 = _mm256_set1_epi32(static_cast<int>(0xCD9E8D57u));
  uint32_t ka = key0, kb = key1;
  for (int round = 0; round < 10; ++round) {
    __m256i hi0, lo0, hi1, lo1;
    mulhilo8(a, m0, hi0, lo0);
    mulhilo8(c, m1, hi1, lo1);
    a = _mm256_xor_si256(_mm256_xor_si256(hi1, b), _mm256_set1_epi32(static_cast<int>(ka)));
    b = lo1;
    c = _mm256_xor_si256(_mm256_xor_si256(hi0, d), _mm256_set1_epi32(static_cast<int>(kb)));
    d = lo0;
    ka += 0x9E3779B9u;
    kb += 0xBB67AE85u;
  }
}

bool has_avx2() {
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}
#endif

}  // namespace

void philox_in_place(uint32_t* w0, uint32_t* w1, uint32_t* w2, uint32_t* w3, size_t n,
                     uint32_t key0, uint32_t key1) {
#if defined(__x86_64__)
  if (n >= 8 && has_avx2()) return philox_avx2(w0, w1, w2, w3, n, key0, key1);
#endif
  philox_scalar(w0, w1, w2, w3, n, key0, key1);
}

}  // namespace curdle
