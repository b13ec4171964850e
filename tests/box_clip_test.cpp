#include "layout/box_clip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// A surveyed outline's kind of polygon: 3,000 corners round a wavy circle, each a little off
// the wave.
Polygon wobbly_outline() {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> wobble(-0.002, 0.002);
  Polygon p;
  for (int i = 0; i < 3000; ++i) {
    const double a = 2 * M_PI * i / 3000;
    const double r = 20000 * (1 + 0.15 * std::sin(7 * a) + wobble(random));
    p.push_back({1234.5 + r * std::cos(a), -987.25 + r * std::sin(a)});
  }
  return p;
}

TEST(BoxClipTest, TheIndexedClipIsThePlainOneToTheBit) {
  const Polygon outline = wobbly_outline();
  const PolygonIndex index(outline);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> at(-30000, 30000), size(0.5, 4000);
  int clipped = 0, whole = 0, empty = 0, left = 0;
  for (int k = 0; k < 3000; ++k) {
    const Rect box{at(random), at(random), size(random), size(random)};
    const std::optional<Polygon> plain = clip_to_box(outline, box);
    ASSERT_EQ(clip_to_box(index, box), plain) << box.x << ", " << box.y;
    if (!plain)
      ++left;
    else if (plain->empty())
      ++empty;
    else if (*plain == rect_polygon(box))
      ++whole;
    else
      ++clipped;
  }
  // Every way a clip can end is met, each many times.
  EXPECT_GT(clipped, 20);
  EXPECT_GT(whole, 20);
  EXPECT_GT(empty, 20);
  EXPECT_GT(left, 20);
  // The box round everything, and boxes off the outline's bounds on every side.
  for (const Rect& box : {Rect{-40000, -40000, 80000, 80000}, Rect{30000, 0, 10, 10},
                          Rect{-40000, 0, 10, 10}, Rect{0, 30000, 10, 10}, Rect{0, -40000, 10, 10}})
    EXPECT_EQ(clip_to_box(index, box), clip_to_box(outline, box));
}

TEST(BoxClipTest, AnIndexSaysWhereAPointIsAsThePolygonDoes) {
  const Polygon outline = wobbly_outline();
  const PolygonIndex index(outline);
  std::mt19937_64 random(13);
  std::uniform_real_distribution<double> at(-30000, 30000);
  for (int k = 0; k < 20000; ++k) {
    const double x = at(random), y = at(random);
    ASSERT_EQ(index.contains_as_polygon(x, y), contains(outline, x, y)) << x << ", " << y;
  }
  for (const auto& [x, y] : outline) {  // on the corners themselves
    EXPECT_EQ(index.contains_as_polygon(x, y), contains(outline, x, y));
  }
}

}  // namespace
}  // namespace curdle
