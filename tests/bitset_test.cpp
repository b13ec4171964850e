// Tests of bitset.h: bits set, cleared, ORed in across word boundaries and visited in order,
// against a std::vector<bool> written alongside.
#include "curdle/bitset.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace curdle {
namespace {

TEST(Bitset, AgreesWithAVectorOfBoolsAcrossWordBoundaries) {
  std::mt19937_64 rng(5);
  for (const uint64_t n : {1u, 63u, 64u, 65u, 200u, 1000u}) {
    Bitset b;
    b.assign_zero(n);
    std::vector<bool> v(n, false);
    for (int i = 0; i < 300; ++i) {
      const uint64_t at = rng() % n;
      if (rng() % 3) {
        b.set(at), v[at] = true;
      } else {
        b.reset(at), v[at] = false;
      }
    }
    // or_bits at every offset that fits, with runs of every length up to 64.
    const uint64_t offset = rng() % n, count = 1 + rng() % std::min<uint64_t>(64, n - offset);
    const uint64_t bits = rng();
    b.or_bits(offset, bits, static_cast<unsigned>(count));
    for (uint64_t k = 0; k < count; ++k)
      if (bits >> k & 1) v[offset + k] = true;
    uint64_t set = 0;
    for (uint64_t i = 0; i < n; ++i) {
      ASSERT_EQ(b.test(i), v[i]) << "bit " << i << " of " << n;
      set += v[i];
    }
    EXPECT_EQ(b.count(), set);
    std::vector<uint64_t> visited, expected;
    const uint64_t begin = n / 3, end = n - n / 5;
    for_each_set(b, begin, end, [&](uint64_t i) { visited.push_back(i); });
    for (uint64_t i = begin; i < end; ++i)
      if (v[i]) expected.push_back(i);
    EXPECT_EQ(visited, expected);
    bool any = false;
    for (uint64_t i = begin; i < end; ++i) any |= v[i];
    EXPECT_EQ(b.any_in(begin, end), any);
  }
}

TEST(Bitset, CopiesAreDeepAndAssignZeroClears) {
  Bitset a;
  a.assign_zero(130);
  a.set(129);
  Bitset b = a;
  b.reset(129);
  EXPECT_TRUE(a.test(129));
  EXPECT_FALSE(b.test(129));
  a.assign_zero(10);  // reusing the buffer: every bit zero again
  EXPECT_EQ(a.count(), 0u);
  EXPECT_FALSE(a.any_in(0, 10));
}

TEST(Bitset, CountsLargeSetsInParallelAsOneWouldByHand) {
  Bitset b;
  b.assign_zero(uint64_t{1} << 22);
  uint64_t expected = 0;
  for (uint64_t i = 0; i < b.size; i += 7) b.set(i), ++expected;
  EXPECT_EQ(b.count(), expected);
}

}  // namespace
}  // namespace curdle
