// Tests of union.h: polygonised circles stay within their tolerance, unions and cuts keep
// their exact areas (CGAL's exact arithmetic).
#include "layout/union.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace curdle {
namespace {

TEST(Union, PolygonisedCirclesStayWithinTheTolerance) {
  const Circle c{50, 20, 30};
  for (const double tolerance : {1.0, 0.05}) {
    const Ring ring = polygonise(c, tolerance);
    ASSERT_GE(ring.size(), 8u);
    for (size_t i = 0; i < ring.size(); ++i) {
      const auto& a = ring[i];
      const auto& b = ring[(i + 1) % ring.size()];
      EXPECT_NEAR(std::hypot(a[0] - c.cx, a[1] - c.cy), 15, 1e-9);  // vertices on the circle
      const double mx = (a[0] + b[0]) / 2 - c.cx, my = (a[1] + b[1]) / 2 - c.cy;
      EXPECT_LE(15 - std::hypot(mx, my), tolerance + 1e-9);  // chords stray at most that far
    }
  }
}

TEST(Union, APolygonisedCirclesBoxIsTheCircles) {
  // The quarter points are vertices: the ring's extent is the circle's, at any size (the
  // schedule's WKT of a 30 mm opening once lay 0.05 mm inside its row's box).
  for (const double d : {3.0, 30.0, 31.7, 450.0, 8000.0})
    for (const double tolerance : {1.0, 0.05, 0.01}) {
      const Circle c{12.5, -7.25, d};
      const Ring ring = polygonise(c, tolerance);
      EXPECT_EQ(ring.size() % 4, 0u) << d;
      double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
      for (const auto& v : ring) {
        lo_x = std::min(lo_x, v[0]), hi_x = std::max(hi_x, v[0]);
        lo_y = std::min(lo_y, v[1]), hi_y = std::max(hi_y, v[1]);
      }
      EXPECT_NEAR(lo_x, c.cx - d / 2, 1e-9 * d) << d << " " << tolerance;
      EXPECT_NEAR(hi_x, c.cx + d / 2, 1e-9 * d) << d << " " << tolerance;
      EXPECT_NEAR(lo_y, c.cy - d / 2, 1e-9 * d) << d << " " << tolerance;
      EXPECT_NEAR(hi_y, c.cy + d / 2, 1e-9 * d) << d << " " << tolerance;
    }
}

TEST(Union, UnionsAndCutsKeepTheirAreas) {
  // Two overlapping circles: the union is one outline, the sum less the lens.
  const std::vector<Outline> two = union_of_circles({{0, 0, 20}, {10, 0, 20}}, 0.001);
  ASSERT_EQ(two.size(), 1u);
  const double r = 10, d = 10;
  const double lens = 2 * r * r * std::acos(d / (2 * r)) - d / 2 * std::sqrt(4 * r * r - d * d);
  // Chords cut off at most the tolerance along the perimeter (under both circles' 2 pi r).
  EXPECT_LE(two[0].area, 2 * std::numbers::pi * r * r - lens);
  EXPECT_NEAR(two[0].area, 2 * std::numbers::pi * r * r - lens,
              0.001 * 2 * 2 * std::numbers::pi * r);
  // Adjacent rectangles join into one; apart they stay two.
  EXPECT_EQ(union_of_rects({{0, 0, 10, 10}, {10, 0, 5, 10}}).size(), 1u);
  EXPECT_EQ(union_of_rects({{0, 0, 10, 10}, {20, 0, 5, 10}}).size(), 2u);
  // A square cut along a sloping edge keeps the part inside the triangle.
  PolygonCuts cuts;
  cuts.outline = {{0, 0}, {100, 0}, {0, 100}};
  const Outline kept = joined(cut_along({Rect{0, 0, 60, 60}}, cuts));
  EXPECT_NEAR(kept.area, 60 * 60 - 20 * 20 / 2.0, 1e-6);
  const std::vector<Outline> away = cut_away(Rect{0, 0, 100, 100}, cuts);
  double gone = 0;
  for (const Outline& o : away) gone += o.area;
  EXPECT_NEAR(gone, 100 * 100 / 2.0, 1e-6);
  EXPECT_NEAR(area_within(Rect{50, 50, 50, 50}, away), 2500, 1e-6);
}

// What an outline cuts away may be two triangles meeting at a point (a gable's top on a
// rectangle): the surface left is the whole less both, whatever shape CGAL hands the pair back in.
TEST(Union, CutAwayPartsMeetingAtAPointAreTakenOffWhole) {
  PolygonCuts cuts;
  cuts.outline = {{0, 0}, {1500, 0}, {1500, 900}, {750, 1200}, {0, 900}};
  const Rect surface{0, 0, 1500, 1200};
  const std::vector<Outline> away = cut_away(surface, cuts);
  double away_area = 0;
  for (const Outline& o : away) away_area += o.area;
  EXPECT_NEAR(away_area, 2 * 750.0 * 300 / 2, 1e-6);
  double left = 0;
  for (const Outline& o : surfaced(surface, {Rect{600, 400, 300, 300}}, away)) left += o.area;
  EXPECT_NEAR(left, 1500.0 * 1200 - 225000 - 90000, 1e-6);
  EXPECT_NEAR(area_within(Rect{0, 0, 1500, 1200}, away), 225000, 1e-6);
}

}  // namespace
}  // namespace curdle
