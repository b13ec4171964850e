// Tests of box_levels.h: each level's occupied boxes are those holding an occupied cell, counted
// by hand, for a box that does not start at a multiple of the base.
#include "curdle/box_levels.h"

#include <gtest/gtest.h>

#include <random>

namespace curdle {
namespace {

TEST(BoxLevels, EachLevelHoldsTheBoxesWithAnOccupiedCell) {
  std::mt19937 rng(11);
  const Box box{{5, 3, 0}, {27, 19, 1}};  // not aligned to base 3
  std::vector<bool> cells(static_cast<size_t>(box.cells()));
  for (size_t i = 0; i < cells.size(); ++i) cells[i] = rng() % 9 == 0;
  int seen = 0;
  for_each_box_level(3, 2, box, cells, 3, [&](const BoxLevel& level) {
    ++seen;
    int64_t side = 1;
    for (int j = 0; j < level.index; ++j) side *= 3;
    EXPECT_EQ(level.side, side);
    for (int64_t by = 0; by < level.count[1]; ++by)
      for (int64_t bx = 0; bx < level.count[0]; ++bx) {
        bool any = false;  // by hand: any cell of the box inside `box`
        for (int64_t y = (level.first[1] + by) * side; y < (level.first[1] + by + 1) * side; ++y)
          for (int64_t x = (level.first[0] + bx) * side; x < (level.first[0] + bx + 1) * side; ++x)
            if (x >= box.origin[0] && x < box.origin[0] + box.size[0] && y >= box.origin[1] &&
                y < box.origin[1] + box.size[1])
              any |=
                  cells[static_cast<size_t>((y - box.origin[1]) * box.size[0] + x - box.origin[0])];
        EXPECT_EQ(level.occupied[static_cast<size_t>(by * level.count[0] + bx)], any)
            << "level " << level.index << " box " << bx << ", " << by;
      }
  });
  EXPECT_EQ(seen, 4);
}

}  // namespace
}  // namespace curdle
