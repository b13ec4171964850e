#include "layout/contour.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "layout/zone.h"

namespace curdle {
namespace {

// A disc of radius 700 at (5000, 4000) as CAD writes a circle in a polyline: two half turns.
Contour disc() { return {{4300, 4000, 1}, {5700, 4000, 1}}; }

TEST(ContourTest, BulgeGivesCentreRadiusAndSweep) {
  // A quarter turn counter-clockwise from (10, 0) to (0, 10) round the origin.
  const Arc a = arc_between({10, 0, std::tan(std::numbers::pi / 8)}, {0, 10, 0});
  EXPECT_NEAR(a.radius, 10, 1e-12);
  EXPECT_NEAR(a.centre[0], 0, 1e-12);
  EXPECT_NEAR(a.centre[1], 0, 1e-12);
  EXPECT_NEAR(a.sweep, std::numbers::pi / 2, 1e-12);
  // Clockwise, the same chord swells the other way: its centre is (10, 10).
  const Arc b = arc_between({10, 0, -std::tan(std::numbers::pi / 8)}, {0, 10, 0});
  EXPECT_NEAR(b.centre[0], 10, 1e-12);
  EXPECT_NEAR(b.centre[1], 10, 1e-12);
  EXPECT_NEAR(b.sweep, -std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(bulge_of_sweep(std::numbers::pi), 1, 1e-12);
}

TEST(ContourTest, AreaIsTheTrueArcs) {
  EXPECT_NEAR(contour_area(disc()), std::numbers::pi * 700 * 700, 1e-6);
  // A 10 m chord with an arc dipping 1 m into a 10 x 9 m rectangle takes the segment away.
  const Contour arched{{0, 0, 0}, {10000, 0, 0}, {10000, 9000, -0.2}, {0, 9000, 0}};
  const Arc a = arc_between(arched[2], arched[3]);
  const double segment =
      a.radius * a.radius / 2 * (std::fabs(a.sweep) - std::sin(std::fabs(a.sweep)));
  EXPECT_NEAR(contour_area(arched), 10000.0 * 9000 - segment, 1e-3);
  EXPECT_NEAR(a.radius, 13000, 1e-9);
}

TEST(ContourTest, ChordsStayWithinTheTolerance) {
  for (const double tolerance : {0.05, 0.5, 5.0}) {
    const Polygon p = flatten(disc(), tolerance);
    for (size_t i = 0; i < p.size(); ++i) {
      const auto& a = p[i];
      const auto& b = p[(i + 1) % p.size()];
      EXPECT_NEAR(std::hypot(a[0] - 5000, a[1] - 4000), 700, 1e-9);  // every corner on the arc
      const double mid = std::hypot((a[0] + b[0]) / 2 - 5000, (a[1] + b[1]) / 2 - 4000);
      EXPECT_LE(700 - mid, tolerance + 1e-9);
    }
    EXPECT_GE(p.size(), 8u);
  }
  EXPECT_GT(flatten(disc(), 0.05).size(), flatten(disc(), 5.0).size());
  // Straight edges stay as they are.
  const Polygon square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(flatten(contour_of(square), 0.05), square);
}

TEST(ContourTest, BoundsReachWhereTheArcSwells) {
  const Rect b = contour_bounds(disc());
  EXPECT_NEAR(b.x, 4300, 1e-9);
  EXPECT_NEAR(b.y, 3300, 1e-9);
  EXPECT_NEAR(b.w, 1400, 1e-9);
  EXPECT_NEAR(b.h, 1400, 1e-9);
  // An arch dipping inwards reaches no further than its ends.
  const Rect a = contour_bounds({{0, 0, 0}, {10000, 0, 0}, {10000, 9000, -0.2}, {0, 9000, 0}});
  EXPECT_NEAR(a.top(), 9000, 1e-9);
}

TEST(ContourTest, ScalingKeepsArcs) {
  const Contour m = transformed(disc(), 0.001, -4.3, -4);  // the disc in metres, moved
  EXPECT_NEAR(contour_area(m), std::numbers::pi * 0.7 * 0.7, 1e-12);
  EXPECT_EQ(arc_count(m), 2u);
  EXPECT_TRUE(has_arcs(m));
}

TEST(ContourTest, FirstCrossingNamesWhereAnOutlineCrossesItself) {
  const Polygon bow{{0, 0}, {10, 10}, {10, 0}, {0, 10}};
  const auto at = first_crossing(bow);
  ASSERT_TRUE(at);
  EXPECT_NEAR((*at)[0], 5, 1e-9);
  EXPECT_NEAR((*at)[1], 5, 1e-9);
  EXPECT_FALSE(first_crossing(flatten(disc(), 0.01)));
  EXPECT_FALSE(is_simple(bow));
  // A surveyed outline of 100,000 corners is checked in one pass of buckets.
  Polygon survey;
  for (int i = 0; i < 100000; ++i) {
    const double t = 2 * std::numbers::pi * i / 100000;
    survey.push_back({1e5 * std::cos(t) * (1 + 0.01 * std::sin(40 * t)), 1e5 * std::sin(t)});
  }
  EXPECT_FALSE(first_crossing(survey));
  std::swap(survey[10], survey[50000]);
  EXPECT_TRUE(first_crossing(survey));
}

}  // namespace
}  // namespace curdle
