// Tests of zone.h.
#include "layout/zone.h"

#include <gtest/gtest.h>

#include <cmath>

#include "layout_support.h"

namespace curdle {
using test::design;

TEST(Geometry, RectilinearPolygonsBecomeRectangles) {
  const Polygon l = {{0, 0}, {3000, 0}, {3000, 1000}, {1000, 1000}, {1000, 2500}, {0, 2500}};
  const auto rects = as_rectangles(l);
  ASSERT_TRUE(rects);
  double area = 0;
  for (const Rect& r : *rects) area += r.area();
  EXPECT_NEAR(area, polygon_area(l), 1e-9);
  EXPECT_FALSE(as_rectangles({{0, 0}, {10, 0}, {10, 10}}));
  EXPECT_TRUE(is_simple(l));
  EXPECT_FALSE(is_simple({{0, 0}, {10, 10}, {10, 0}, {0, 10}}));  // a bow tie
  EXPECT_TRUE(contains(l, 500, 2000));
  EXPECT_FALSE(contains(l, 2000, 2000));
}

}  // namespace curdle

namespace curdle {

// An outline's outer rings run anticlockwise (positive), its islands clockwise; a point inside
// a ring lies inside it however it bends (an L's corner is outside it).
TEST(Geometry, SignedAreaAndAPointInsideARing) {
  const Polygon l = {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};
  EXPECT_DOUBLE_EQ(signed_area(l), 7);
  EXPECT_DOUBLE_EQ(signed_area(Polygon(l.rbegin(), l.rend())), -7);
  EXPECT_DOUBLE_EQ(polygon_area(Polygon(l.rbegin(), l.rend())), 7);
  const auto p = point_inside(l);
  ASSERT_TRUE(p);
  EXPECT_TRUE(contains(l, (*p)[0], (*p)[1]));
  EXPECT_FALSE(point_inside(Polygon{{0, 0}, {1, 1}}));
}

TEST(Geometry, DistanceToASegmentIsToItsNearestPointEndsIncluded) {
  EXPECT_DOUBLE_EQ(distance_to_segment({5, 3}, {0, 0}, {10, 0}), 3);   // over its middle
  EXPECT_DOUBLE_EQ(distance_to_segment({13, 4}, {0, 0}, {10, 0}), 5);  // past its end
  EXPECT_DOUBLE_EQ(distance_to_segment({3, 4}, {1, 1}, {1, 1}), std::hypot(2, 3));  // a point
  EXPECT_DOUBLE_EQ(distance_to_edges(Polygon{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, 4, 3), 3);
}

}  // namespace curdle
