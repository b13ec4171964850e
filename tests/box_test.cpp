// Tests of box.h: cells, containment and well-formedness of boxes of cells, and flooring
// division of negative coordinates.
#include "curdle/box.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(Box, CountsCellsAndContainsWhatLiesInside) {
  const Box field{{0, 0, 0}, {64, 32, 1}};
  EXPECT_EQ(field.cells(), 2048u);
  EXPECT_TRUE(field.well_formed());
  EXPECT_TRUE(field.contains(Box{{10, 10, 0}, {54, 22, 1}}));   // to the far edge
  EXPECT_FALSE(field.contains(Box{{10, 10, 0}, {55, 22, 1}}));  // one past it
  EXPECT_FALSE(field.contains(Box{{0, 0, 0}, {0, 1, 1}}));      // empty
  EXPECT_FALSE((Box{{0, 0, 0}, {0, 1, 1}}).well_formed());
  EXPECT_FALSE((Box{{-1, 0, 0}, {1, 1, 1}}).well_formed());
}

TEST(Box, FloorDivisionRoundsTowardsMinusInfinity) {
  EXPECT_EQ(floor_div(7, 2), 3);
  EXPECT_EQ(floor_div(-7, 2), -4);
  EXPECT_EQ(floor_div(-8, 2), -4);
  EXPECT_EQ(floor_div(0, 5), 0);
}

}  // namespace
}  // namespace curdle
