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

#include <random>

#include "curdle/extinction.h"
#include "curdle/fit.h"

namespace curdle {
namespace {

// Canonical curdling written here, with the standard library's generator (not curdle's
// engine): every child of a surviving cell survives stage k with probability p[k - 1].
std::vector<bool> curdle_here(int base, int64_t width, int64_t height, const std::vector<double>& p,
                              uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const int K = static_cast<int>(p.size());
  int64_t side = 1;
  for (int k = 0; k < K; ++k) side *= base;
  // Survival of each stage's cells over the whole roots covering the field, coarse to fine.
  int64_t cols = (width + side - 1) / side, rows = (height + side - 1) / side;
  std::vector<bool> alive(static_cast<size_t>(cols * rows), true);
  for (int k = 1; k <= K; ++k) {
    const int64_t nc = cols * base, nr = rows * base;
    std::vector<bool> next(static_cast<size_t>(nc * nr), false);
    for (int64_t y = 0; y < nr; ++y)
      for (int64_t x = 0; x < nc; ++x)
        next[static_cast<size_t>(y * nc + x)] =
            alive[static_cast<size_t>((y / base) * cols + x / base)] && u(rng) < p[k - 1];
    alive = std::move(next);
    cols = nc, rows = nr;
  }
  std::vector<bool> field(static_cast<size_t>(width * height));
  for (int64_t y = 0; y < height; ++y)
    for (int64_t x = 0; x < width; ++x)
      field[static_cast<size_t>(y * width + x)] = alive[static_cast<size_t>(y * cols + x)];
  return field;
}

}  // namespace

TEST(Fit, CurdsMadeHereAreFittedBackToTheirProbabilities) {
  // 16 x 12 roots cropped to 1000 x 700 cells; probabilities that rise and fall.
  const std::vector<double> p{0.9, 0.6, 0.85, 0.7, 0.8, 0.65};
  const Lattice l{2, 2, 6, Mode::canonical};
  const Box field{{0, 0, 0}, {1000, 700, 1}};
  for (uint32_t seed : {1u, 2u, 3u}) {
    const auto cells = curdle_here(2, 1000, 700, p, seed);
    const auto measured = occupied_cells(l, field, cells);
    const auto fit = fit_probabilities(l, field, measured);
    ASSERT_EQ(fit.size(), p.size());
    for (size_t k = 0; k < p.size(); ++k) {
      // Stated bound: 4 standard deviations of the estimate. The expected counts with the
      // fitted probabilities follow the measured ones, stage to stage (the roots that keep a
      // survivor, N_0, are what they are: no probability sets them).
      EXPECT_NEAR(fit[k].probability, p[k], 4 * fit[k].sd) << "seed " << seed << " stage " << k + 1;
      EXPECT_NEAR(fit[k].expected / static_cast<double>(fit[k].measured), 1.0, 1e-3);
    }
  }
}

TEST(Fit, OccupiedCellsAreTheBoxCounts) {
  const Lattice l{3, 2, 2, Mode::canonical};
  const Box field{{0, 0, 0}, {10, 4, 1}};
  std::vector<bool> cells(40, false);
  cells[0] = cells[9] = cells[3 * 10 + 4] = true;  // (0,0), (9,0), (4,3)
  EXPECT_EQ(occupied_cells(l, field, cells), (std::vector<uint64_t>{2, 3, 3}));
}

}  // namespace curdle
