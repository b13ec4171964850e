// Tests of survival_bytes.h: the vector comparison of survival bytes agrees with comparing
// each byte by hand, for one draw and for lanes of draws.
#include "curdle/survival_bytes.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace curdle {
namespace {

uint8_t byte_of(const uint32_t w[4], int b) {
  return static_cast<uint8_t>(w[b / 4] >> 8 * (b % 4));
}

TEST(SurvivalBytes, BelowAndTieAreEachBytesComparisonWithTheTop) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 200; ++trial) {
    const uint32_t top = rng() % 256;
    RandomStream::Block r;
    uint32_t w[4];
    for (int i = 0; i < 4; ++i) {
      w[i] = rng();
      if (trial % 3 == 0) w[i] = top * 0x01010101u ^ (rng() % 2 ? 0 : 0x00ff0000u);  // ties
      r[i] = w[i];
    }
    uint32_t below = 0, tie = 0;
    compare_bytes(r, top, below, tie);
    uint16_t lane_below = 0, lane_tie = 0;
    compare_lanes(&w[0], &w[1], &w[2], &w[3], 1, top, &lane_below, &lane_tie);
    for (int b = 0; b < 16; ++b) {
      EXPECT_EQ(below >> b & 1, byte_of(w, b) < top ? 1u : 0u) << "byte " << b;
      EXPECT_EQ(tie >> b & 1, byte_of(w, b) == top ? 1u : 0u) << "byte " << b;
    }
    EXPECT_EQ(lane_below, below);
    EXPECT_EQ(lane_tie, tie);
  }
}

}  // namespace
}  // namespace curdle
