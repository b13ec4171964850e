// A flat bit array: one bit per cell of one stage of one curd.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace curdle {

// Zeroed 64-bit words. Large buffers come straight from the kernel (already zero, on huge
// pages where it allows), so that a fresh stage is neither faulted in page by page nor
// cleared twice; smaller ones are reused between calls.
class Words {
 public:
  Words() = default;
  Words(const Words& other);
  Words(Words&& other) noexcept;
  Words& operator=(Words other) noexcept;
  ~Words();

  void assign_zero(size_t count);  // `count` zero words, reusing the buffer when it is large enough
  uint64_t* data() { return data_; }
  const uint64_t* data() const { return data_; }
  size_t size() const { return size_; }
  uint64_t& operator[](size_t i) { return data_[i]; }
  uint64_t operator[](size_t i) const { return data_[i]; }
  const uint64_t* begin() const { return data_; }
  const uint64_t* end() const { return data_ + size_; }
  bool operator==(const Words& other) const {
    return std::equal(begin(), end(), other.begin(), other.end());
  }

 private:
  void release();
  uint64_t* data_ = nullptr;
  size_t size_ = 0;
  size_t capacity_ = 0;
  size_t mapped_bytes_ = 0;  // non-zero when the buffer is an anonymous mapping
};

struct Bitset {
  Words words;
  uint64_t size = 0;

  // Resizes to n zero bits.
  void assign_zero(uint64_t n) {
    size = n;
    words.assign_zero((n + 63) / 64);
  }
  bool test(uint64_t i) const { return (words[i >> 6] >> (i & 63)) & 1; }
  void set(uint64_t i) { words[i >> 6] |= uint64_t{1} << (i & 63); }
  void reset(uint64_t i) { words[i >> 6] &= ~(uint64_t{1} << (i & 63)); }

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

  uint64_t count() const;  // set bits; in parallel for large sets
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
