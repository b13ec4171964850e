#include "layout/box_clip.h"

#include <gtest/gtest.h>

#include "layout/zone.h"

namespace curdle {
namespace {

// An L: 10 x 10 less its top-right 6 x 6 quarter.
const Polygon kEll{{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};

TEST(BoxClipTest, OnePieceIsClippedExactly) {
  const auto part = clip_to_box(kEll, Rect{2, 2, 4, 4});  // round the inner corner
  ASSERT_TRUE(part);
  EXPECT_DOUBLE_EQ(polygon_area(*part), 16 - 4);  // the box less the 2 x 2 beyond the corner
  for (const auto& p : *part) {
    EXPECT_GE(p[0], 2);
    EXPECT_LE(p[0], 6);
  }
}

TEST(BoxClipTest, InsideOutsideAndAround) {
  EXPECT_EQ(clip_to_box(kEll, Rect{1, 1, 1, 1}), rect_polygon(Rect{1, 1, 1, 1}));
  EXPECT_EQ(clip_to_box(kEll, Rect{7, 7, 2, 2}), Polygon{});
  EXPECT_EQ(clip_to_box(kEll, Rect{-5, -5, 30, 30}), kEll);
}

TEST(BoxClipTest, SeveralPiecesAreLeftToTheCaller) {
  // A U whose two arms both reach into the box: two pieces, which clipping would bridge.
  const Polygon u{{0, 0}, {9, 0}, {9, 9}, {6, 9}, {6, 3}, {3, 3}, {3, 9}, {0, 9}};
  EXPECT_FALSE(clip_to_box(u, Rect{1, 5, 7, 2}));
  // Touching the box's side from outside is not an exact clip either.
  const Polygon touching{{0, 0}, {4, 0}, {5, 2}, {6, 0}, {10, 0}, {10, -5}, {0, -5}};
  EXPECT_FALSE(clip_to_box(touching, Rect{3, 2, 4, 4}));
}

}  // namespace
}  // namespace curdle
