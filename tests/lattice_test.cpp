// Tests of lattice.h: children, sides and cells per root of a lattice b, E, K.
#include "curdle/lattice.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(Lattice, SidesAndCountsArePowersOfTheBase) {
  const Lattice l{3, 2, 4, Mode::canonical};
  EXPECT_EQ(l.children(), 9u);
  EXPECT_EQ(l.root_side(), 81u);
  EXPECT_EQ(l.cells_per_root(0), 1u);
  EXPECT_EQ(l.cells_per_root(2), 81u);
  EXPECT_EQ(l.side_in_cells(0), 81u);
  EXPECT_EQ(l.side_in_cells(4), 1u);
  const Lattice cube{2, 3, 5, Mode::exact};
  EXPECT_EQ(cube.children(), 8u);
  EXPECT_EQ(cube.cells_per_root(5), 32768u);
  EXPECT_EQ(to_string(Mode::canonical), "canonical");
  EXPECT_EQ(to_string(Mode::quota), "quota");
}

}  // namespace
}  // namespace curdle
