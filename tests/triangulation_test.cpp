// Tests of triangulation.h: the triangles of a polygon with a hole cover its area exactly.
#include "layout/triangulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace curdle {
namespace {

TEST(Triangulation, TrianglesCoverThePolygonLessItsHoles) {
  const Ring outer{{0, 0}, {100, 0}, {100, 60}, {50, 100}, {0, 60}};  // counter-clockwise
  const Ring hole{{40, 20}, {40, 40}, {60, 40}, {60, 20}};            // clockwise
  double area = 0;
  for (const auto& t : triangulate({outer, hole}))
    area += std::fabs((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) -
                      (t[2][0] - t[0][0]) * (t[1][1] - t[0][1])) /
            2;
  EXPECT_NEAR(area, 100 * 60 + 100 * 40 / 2.0 - 20 * 20, 1e-6);
}

}  // namespace
}  // namespace curdle
