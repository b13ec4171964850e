// Tests of merge_runs.h.
#include "layout/merge_runs.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
using test::design;

TEST(Geometry, MergedRunsCoverEveryCellOnce) {
  std::mt19937 rng(5);
  const int64_t rows = 37, cols = 53;
  std::vector<int> grid(rows * cols);
  for (auto& v : grid) v = static_cast<int>(rng() % 4) - 1;  // -1: not merged
  std::vector<int> seen(grid.size(), 0);
  for (const GridRect& g : merge_runs(grid, rows, cols))
    for (int64_t r = g.row0; r <= g.row1; ++r)
      for (int64_t c = g.column0; c <= g.column1; ++c) {
        EXPECT_EQ(grid[r * cols + c], g.value);
        ++seen[r * cols + c];
      }
  for (size_t i = 0; i < grid.size(); ++i) EXPECT_EQ(seen[i], grid[i] >= 0 ? 1 : 0);
}

}  // namespace curdle
