// Tests of polygon_crossing.h.
#include "layout/polygon_crossing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace curdle {
namespace {

// A star of `spikes` points from radius `inner` to `outer` round (0, 0): simple, its long edges
// all meeting near the middle.
Polygon star(int spikes, double inner, double outer) {
  Polygon p;
  for (int i = 0; i < 2 * spikes; ++i) {
    const double a = std::numbers::pi * i / spikes, r = i % 2 ? inner : outer;
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

TEST(PolygonCrossing, NeighboursMeetAtTheirVertexAndNoWhereElse) {
  EXPECT_FALSE(first_crossing({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  EXPECT_FALSE(first_crossing({{0, 0}, {10, 0}, {10, 10}}));  // a triangle has no other pairs
  // A corner that touches a far edge is a crossing, where it touches.
  const auto touch = first_crossing({{0, 0}, {10, 0}, {10, 10}, {5, 0}, {0, 10}});
  ASSERT_TRUE(touch);
  EXPECT_NEAR((*touch)[0], 5, 1e-9);
  EXPECT_NEAR((*touch)[1], 0, 1e-9);
  // Edges that overlap along a line, and a bow tie.
  EXPECT_TRUE(first_crossing({{0, 0}, {10, 0}, {10, 5}, {8, 0}, {2, 0}, {0, 5}}));
  const auto bow = first_crossing({{0, 0}, {10, 10}, {10, 0}, {0, 10}});
  ASSERT_TRUE(bow);
  EXPECT_NEAR((*bow)[0], 5, 1e-9);
}

TEST(PolygonCrossing, AStarOfLongSpikesIsCheckedAndOneBentSpikeFound) {
  // Filed under every cell its box covers, each of these edges went into a quarter of the grid
  // (at 10,000 corners, a recipe's limit, that took 63 s; now 0.75 s).
  Polygon p = star(1000, 200, 5000);
  EXPECT_FALSE(first_crossing(p));
  // One outer corner pulled across its neighbour spike.
  p[200] = {p[202][0] * 0.5 + p[204][0] * 0.5, p[202][1] * 0.5 + p[204][1] * 0.5};
  EXPECT_TRUE(first_crossing(p));
}

TEST(PolygonCrossing, EdgesLongerThanTheGridStillMeetTheShortOnes) {
  // A comb: 2,000 short teeth along one side and one long edge back, which a tooth touches.
  Polygon comb;
  for (int i = 0; i < 1000; ++i) comb.push_back({i * 10.0, 0}), comb.push_back({i * 10.0 + 5, 3});
  comb.push_back({10000, 0});
  comb.push_back({10000, -50});
  comb.push_back({0, -50});
  EXPECT_FALSE(first_crossing(comb));
  comb[501] = {comb[501][0], -50};  // a tooth reaching down to the long edge
  EXPECT_TRUE(first_crossing(comb));
}

}  // namespace
}  // namespace curdle
