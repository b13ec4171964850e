// A flat bit array: one bit per cell of one stage of one curd.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

namespace curdle {

struct Bitset {
  std::vector<uint64_t> words;
  uint64_t size = 0;

  // Resizes to n zero bits, keeping the allocation when it is large enough.
  void assign_zero(uint64_t n) {
    size = n;
    words.assign((n + 63) / 64, 0);
  }
  bool test(uint64_t i) const { return (words[i >> 6] >> (i & 63)) & 1; }
  void set(uint64_t i) { words[i >> 6] |= uint64_t{1} << (i & 63); }

  // ORs the low `count` (<= 64) bits of `bits` in at bit `offset`.
  void or_bits(uint64_t offset, uint64_t bits, unsigned count) {
    if (count < 64) bits &= (uint64_t{1} << count) - 1;
    const uint64_t w = offset >> 6;
    const unsigned s = offset & 63;
    words[w] |= bits << s;
    if (s != 0 && s + count > 64) words[w + 1] |= bits >> (64 - s);
  }

  // True when any bit in [begin, end) is set.
  bool any_in(uint64_t begin, uint64_t end) const {
    while (begin < end) {
      const uint64_t w = begin >> 6;
      const unsigned s = begin & 63;
      const uint64_t span = std::min<uint64_t>(64 - s, end - begin);
      uint64_t m = words[w] >> s;
      if (span < 64) m &= (uint64_t{1} << span) - 1;
      if (m) return true;
      begin += span;
    }
    return false;
  }

  uint64_t count() const {
    uint64_t n = 0;
    for (uint64_t w : words) n += std::popcount(w);
    return n;
  }
};

// Calls f(i) for every set bit i in [begin, end), in increasing order.
template <class F>
inline void for_each_set(const Bitset& b, uint64_t begin, uint64_t end, F&& f) {
  if (begin >= end) return;
  uint64_t w = begin >> 6;
  const uint64_t last = (end - 1) >> 6;
  uint64_t m = b.words[w] & (~uint64_t{0} << (begin & 63));
  for (;;) {
    if (w == last && (end & 63)) m &= (uint64_t{1} << (end & 63)) - 1;
    while (m) {
      f((w << 6) + std::countr_zero(m));
      m &= m - 1;
    }
    if (++w > last) break;
    m = b.words[w];
  }
}

}  // namespace curdle
