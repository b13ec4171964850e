// Tests of park_placing.h.
#include "kinds/park_placing.h"

#include <gtest/gtest.h>

#include <set>

namespace curdle {

// The draws are a pure function of (seed, cell, member, attempt), in [0, 1), and differ from
// cell to cell, member to member and seed to seed.
TEST(ParkPlacing, DrawsArePureAndDifferByCellMemberAndSeed) {
  EXPECT_EQ(placing_draws(5, 3, 4, 1, 0), placing_draws(5, 3, 4, 1, 0));
  std::set<double> firsts;
  for (int64_t x = 0; x < 20; ++x)
    for (int64_t y = 0; y < 20; ++y)
      for (const double u : placing_draws(5, x, y, 0, 0)) {
        EXPECT_GE(u, 0.0);
        EXPECT_LT(u, 1.0);
        firsts.insert(u);
      }
  EXPECT_EQ(firsts.size(), 1600u);
  EXPECT_NE(placing_draws(5, 3, 4, 1, 0), placing_draws(5, 3, 4, 2, 0));
  EXPECT_NE(placing_draws(5, 3, 4, 1, 0), placing_draws(6, 3, 4, 1, 0));
  EXPECT_NE(placing_draws(5, 3, 4, 1, 0), placing_draws(5, 3, 4, 1, 1));
}

// Towards the nearest target, square to the grid; from inside one, across it by the nearest
// edge; nothing when there is nothing to face.
TEST(ParkPlacing, BearingsPointToTheNearestTargetSquareToTheGrid) {
  const std::vector<Rect> path{{0, 10000, 20000, 2000}, {30000, 0, 2000, 20000}};
  EXPECT_EQ(bearing_towards({5000, 5000}, path), 0);     // the path north of it
  EXPECT_EQ(bearing_towards({27000, 5000}, path), 90);   // the path east of it is nearer
  EXPECT_EQ(bearing_towards({5000, 15000}, path), 180);  // north of the path: south
  EXPECT_EQ(bearing_towards({40000, 5000}, path), 270);  // east of it: west
  EXPECT_EQ(bearing_towards({5000, 10500}, path), 0);    // on it, by its south edge
  EXPECT_EQ(bearing_towards({5000, 5000}, std::vector<Rect>{}), std::nullopt);
  const Polygon lawn{{20000, 0}, {24000, 0}, {24000, 24000}, {20000, 24000}};
  EXPECT_EQ(bearing_towards({5000, 5000}, lawn), 90);
  EXPECT_EQ(bearing_towards({21000, 12000}, lawn), 90);  // inside: towards its middle
  EXPECT_EQ(bearing_towards({23500, 12000}, lawn), 270);
}

}  // namespace curdle
