// Tests of curve_stations.h.
#include "layout/curve_stations.h"

#include <gtest/gtest.h>

#include "layout/contour.h"

namespace curdle {
namespace {

// The café park's site: a sloping street edge (one edge) and a west edge that follows a curve
// given as 14 chords. Only the curve is a free curve: set out every 2 m of y by its x, where each
// chord's corner had a tick (66 overlapping numbers on an office's spline).
TEST(CurveStations, AFreeCurveIsSetOutByOffsetsAtRoundStations) {
  const Polygon site{{2000, 0},     {30000, 0},    {30000, 14000}, {24000, 20000}, {2000, 20000},
                     {1500, 18700}, {1080, 17360}, {735, 15990},   {470, 14590},   {280, 13170},
                     {165, 11740},  {125, 10000},  {165, 8260},    {280, 6830},    {470, 5410},
                     {735, 4010},   {1080, 2640},  {1500, 1300}};
  const Contour c = contour_of(site);
  const std::vector<CurveStations> curves = curve_stations(c);
  ASSERT_EQ(curves.size(), 1u);
  const CurveStations& west = curves[0];
  EXPECT_EQ(west.first, 4u);
  EXPECT_EQ(west.last, 0u);
  EXPECT_FALSE(west.along_x);
  EXPECT_EQ(west.step, 2000);
  ASSERT_EQ(west.points.size(), 11u);
  for (size_t i = 0; i < west.points.size(); ++i)
    EXPECT_EQ(west.points[i][1], 2000.0 * static_cast<double>(i));
  EXPECT_DOUBLE_EQ(west.points[5][0], 125);  // a corner on a station
  EXPECT_DOUBLE_EQ(west.points[0][0], 2000);
  // y = 2000 lies on the chord from (1080, 2640) to (1500, 1300).
  EXPECT_NEAR(west.points[1][0], 1500 + (1080 - 1500) * (2000 - 1300) / (2640.0 - 1300), 1e-9);
  for (size_t i = 0; i < site.size(); ++i)
    EXPECT_EQ(inside_a_curve(curves, i, site.size()), i >= 5) << i;
}

// Edges along x or y, an arc (it has a centre), a lone sloping edge and a sharp turn are no
// free curve.
TEST(CurveStations, CornersArcsAndSharpTurnsAreNoCurve) {
  EXPECT_TRUE(curve_stations(contour_of({{0, 0}, {4000, 0}, {4000, 3000}, {0, 3000}})).empty());
  EXPECT_TRUE(curve_stations(contour_of({{0, 0}, {4000, 0}, {4000, 2000}, {2000, 3000}, {0, 3000}}))
                  .empty());
  // A zig-zag: each edge turns 90 degrees from the last.
  EXPECT_TRUE(curve_stations(contour_of({{0, 0},
                                         {1000, 1000},
                                         {2000, 0},
                                         {3000, 1000},
                                         {4000, 0},
                                         {4000, -2000},
                                         {0, -2000}}))
                  .empty());
  Contour arc = contour_of({{0, 0}, {4000, 0}, {4000, 3000}, {0, 3000}});
  arc[1].bulge = 0.3;
  EXPECT_TRUE(curve_stations(arc).empty());
}

}  // namespace
}  // namespace curdle
