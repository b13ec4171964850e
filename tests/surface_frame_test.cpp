// Tests of surface_frame.h: points of a straight and a curved façade placed in the building,
// inwards to the wall's inside, and spans of the strip split across frames and round the
// closing corner.
#include "layout/surface_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace curdle {
namespace {

TEST(SurfaceFrame, AStraightFacadePlacesItsFaceAndTheInsideOnTheLeft) {
  SurfaceFrame south;  // from (0, 0) to (20000, 0): its outside looks south
  south.to = {20000, 0};
  south.length = 20000;
  south.base = 500;
  const BuildingPoint p = frame_point(south, 5000, 1000, 100);
  EXPECT_NEAR(p[0], 5000, 1e-9);
  EXPECT_NEAR(p[1], 100, 1e-9);  // inside is north of a south face
  EXPECT_NEAR(p[2], 1500, 1e-9);
}

TEST(SurfaceFrame, AnArcPlacesItsFaceOnTheCircleAndInsideTowardsTheCentre) {
  // A quarter circle of radius 12 m about the origin, anticlockwise from (12000, 0).
  SurfaceFrame arc;
  arc.from = {12000, 0};
  arc.to = {0, 12000};
  arc.bulge = std::tan(std::numbers::pi / 8);
  arc.length = 12000 * std::numbers::pi / 2;
  const BuildingPoint mid = frame_point(arc, arc.length / 2, 0, 100);
  EXPECT_NEAR(std::hypot(mid[0], mid[1]), 11900, 1e-6);
  EXPECT_NEAR(mid[0], mid[1], 1e-6);
  const auto d = frame_direction(arc, 0);
  EXPECT_NEAR(d[0], 0, 1e-9);
  EXPECT_NEAR(d[1], 1, 1e-9);
}

TEST(SurfaceFrame, SpansSplitAtFramesAndRoundTheClosingCorner) {
  std::vector<SurfaceFrame> frames(2);
  frames[0].length = 1000;
  frames[1].start = 1000, frames[1].length = 500;
  const auto across = framed_spans(frames, 1500, 900, 1100);
  ASSERT_EQ(across.size(), 2u);
  EXPECT_EQ(across[0].frame, &frames[0]);
  EXPECT_DOUBLE_EQ(across[1].to, 1100);
  const auto wrapped = framed_spans(frames, 1500, 1400, 1600);
  ASSERT_EQ(wrapped.size(), 2u);
  EXPECT_EQ(wrapped[1].frame, &frames[0]);
  EXPECT_DOUBLE_EQ(wrapped[1].to, 100);
  EXPECT_DOUBLE_EQ(wrap_along(1550, 1500), 50);
  EXPECT_EQ(frame_at(frames, 1200), &frames[1]);
  EXPECT_EQ(frame_at(frames, 1500), &frames[1]);
}

}  // namespace
}  // namespace curdle
