// Measuring pictures: exact fractals drawn here come back with their dimensions, shares and
// counts; quantisation finds the levels of a picture.
#include "curdle/measure.h"

#include <gtest/gtest.h>

#include <cmath>

namespace curdle {
namespace {

// A picture where `ink(x, y)` is value 1 (dark) and the rest value 0.
template <class Ink>
ValueGrid picture(int64_t side, Ink ink) {
  ValueGrid g{side, side, std::vector<uint16_t>(static_cast<size_t>(side * side), 0)};
  for (int64_t y = 0; y < side; ++y)
    for (int64_t x = 0; x < side; ++x) g.values[static_cast<size_t>(y * side + x)] = ink(x, y);
  return g;
}

bool carpet(int64_t x, int64_t y) {  // no base-3 digit position has both digits 1
  for (; x || y; x /= 3, y /= 3)
    if (x % 3 == 1 && y % 3 == 1) return false;
  return true;
}

bool cantor(int64_t x) {  // no base-3 digit 1
  for (; x; x /= 3)
    if (x % 3 == 1) return false;
  return true;
}

}  // namespace

TEST(Measure, ASierpinskiCarpetHasDimensionLog8OverLog3) {
  // Six levels: the carpet keeps (8/9)^6 = 49 % of the picture, so it is not the ground.
  const Measurement m =
      measure(picture(729, [](int64_t x, int64_t y) { return carpet(x, y); }), 2, 3);
  const ValueMeasure& ink = m.values[1];
  ASSERT_FALSE(ink.most_common);
  ASSERT_TRUE(ink.fit);
  EXPECT_NEAR(ink.fit->slope, std::log(8.0) / std::log(3.0), 0.02);
  EXPECT_EQ(ink.count, 262144u);  // 8^6 pixels
  EXPECT_EQ(ink.sizes, (std::vector<int64_t>{1, 3, 9, 27, 81, 243, 729}));
  EXPECT_EQ(ink.counts, (std::vector<uint64_t>{262144, 32768, 4096, 512, 64, 8, 1}));
}

TEST(Measure, ACantorDustHasDimensionLog4OverLog3) {
  const Measurement m =
      measure(picture(243, [](int64_t x, int64_t y) { return cantor(x) && cantor(y); }), 2, 3);
  ASSERT_TRUE(m.values[1].fit);
  EXPECT_NEAR(m.values[1].fit->slope, std::log(4.0) / std::log(3.0), 0.02);
  EXPECT_TRUE(m.values[0].most_common);
  EXPECT_FALSE(m.values[0].fit);  // the ground is not fitted
  EXPECT_NEAR(m.values[1].share, 1024.0 / (243 * 243), 1e-12);
}

TEST(Measure, ASierpinskiTriangleMeasuredInPowersOfTwo) {
  // Pascal's triangle mod 2: x & y == 0; N(2^j) = 3^(8-j) on 256 pixels.
  const Measurement m =
      measure(picture(256, [](int64_t x, int64_t y) { return (x & y) == 0; }), 2, 2);
  const ValueMeasure& ink = m.values[1].most_common ? m.values[0] : m.values[1];
  ASSERT_TRUE(ink.fit);
  EXPECT_NEAR(ink.fit->slope, std::log(3.0) / std::log(2.0), 0.02);
  EXPECT_GT(*m.values[1].lacunarity, 1.0);  // clumps and gaps
}

TEST(Measure, QuantisingFindsThePicturesLevels) {
  std::vector<float> lum;
  for (int i = 0; i < 300; ++i) lum.push_back(i % 3 == 0 ? 0.9f : i % 3 == 1 ? 0.5f : 0.1f);
  std::vector<double> levels;
  const ValueGrid g = quantise(30, 10, lum, 3, levels);
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_NEAR(levels[0], 0.9, 1e-3);  // value 0 the lightest, to a bin of 1/4095
  EXPECT_NEAR(levels[1], 0.5, 1e-3);
  EXPECT_NEAR(levels[2], 0.1, 1e-3);
  for (size_t i = 0; i < lum.size(); ++i) EXPECT_EQ(g.values[i], i % 3);
  const ValueGrid t = threshold(30, 10, lum, 0.3);
  for (size_t i = 0; i < lum.size(); ++i) EXPECT_EQ(t.values[i], i % 3 == 2 ? 1 : 0);
}

}  // namespace curdle
