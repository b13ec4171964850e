#include "site/dxf_spline.h"

#include <gtest/gtest.h>

#include <cmath>

#include "dxf_groups_support.h"

namespace curdle::site {
namespace {

using testing::EntityGroups;

const char* const kQuarter =
    "70\n8\n71\n3\n74\n5\n11\n1000\n21\n0\n11\n923.88\n21\n382.68\n11\n707.11\n21\n707.11\n"
    "11\n382.68\n21\n923.88\n11\n0\n21\n1000\n";

TEST(DxfSplineTest, FitPointsAloneAreDrawnThroughAsCadDraws) {
  const EntityGroups e(kQuarter);
  const SplineReading s = read_spline(e.groups, e.numbers, "SPLINE 51", 0.05);
  EXPECT_TRUE(s.fitted);
  EXPECT_TRUE(s.why.empty());
  ASSERT_GT(s.points.size(), 20u);
  for (const Point& p : s.points) EXPECT_NEAR(std::hypot(p[0], p[1]), 1000, 2.0);
}

TEST(DxfSplineTest, WhatCannotBeDrawnSaysWhy) {
  const EntityGroups closed(std::string("70\n9\n") + (kQuarter + 5));
  EXPECT_NE(read_spline(closed.groups, closed.numbers, "SPLINE 51", 0.05)
                .why.find("is a closed spline given only by fit points"),
            std::string::npos);
  // Five control points need nine knots, not two.
  const EntityGroups knots(
      "71\n3\n40\n0\n40\n1\n10\n0\n20\n0\n10\n1\n20\n1\n10\n2\n20\n0\n10\n3\n20\n1\n10\n4\n20\n0"
      "\n");
  const SplineReading s = read_spline(knots.groups, knots.numbers, "SPLINE 52", 0.05);
  EXPECT_NE(s.why.find("cannot be drawn: its 2 knots, 5 control points (degree 3)"),
            std::string::npos)
      << s.why;
  EXPECT_EQ(s.last[0], 4);
  const EntityGroups tilted("10\n0\n20\n0\n30\n0\n10\n1\n20\n1\n30\n5\n");
  EXPECT_FALSE(read_spline(tilted.groups, tilted.numbers, "SPLINE 53", 0.05).flat);
}

}  // namespace
}  // namespace curdle::site
