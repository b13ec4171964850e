// Tests of fit.h: curds made here are fitted back to their probabilities, and the occupied
// cells of each stage are its box counts.
#include "curdle/fit.h"

#include <gtest/gtest.h>

#include <random>

#include "curdle/extinction.h"
#include "curdle/measure.h"

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
