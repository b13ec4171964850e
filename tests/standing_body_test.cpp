// Tests of standing_body.h: how tall each kind of body stands, and a tree's volume.
#include "layout/standing_body.h"

#include <gtest/gtest.h>

#include <cmath>

namespace curdle {

TEST(StandingBody, PiecesBlocksTreesAndBenches) {
  Layout layout;
  layout.thickness = 30;
  layout.level_height = 3000;
  Element piece;
  EXPECT_EQ(body_height(layout, piece), 30);
  EXPECT_EQ(body_volume(piece), -1);  // a prism of its area
  Element block;
  block.form = ElementForm::block;
  EXPECT_EQ(body_height(layout, block), 3000);
  Element tree;
  tree.stands = true;
  tree.circle = Circle{0, 0, 4000};
  EXPECT_EQ(body_height(layout, tree), kTrunkHeight + 4000);
  const double pi = 3.14159265358979323846;
  EXPECT_NEAR(body_volume(tree), pi * 0.1 * 0.1 * 2.2 + pi * 2 * 2 * 4, 1e-9);
  Element bench;
  bench.stands = true;
  EXPECT_EQ(body_height(layout, bench), kStandingHeight);
}

}  // namespace curdle
