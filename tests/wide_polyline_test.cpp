#include "site/wide_polyline.h"

#include <gtest/gtest.h>

namespace curdle::site {
namespace {

TEST(WidePolylineTest, AnLIsMitredAtItsCorner) {
  const Contour c =
      swept_outline({{0, 0, 0, 150, 150}, {1000, 0, 0, 150, 150}, {1000, 500, 0, 0, 0}}, 0.05);
  EXPECT_NEAR(contour_area(c), 150.0 * 1500, 1e-6);
  const Rect b = contour_bounds(c);
  EXPECT_NEAR(b.x, 0, 1e-9);
  EXPECT_NEAR(b.y, -75, 1e-9);
  EXPECT_NEAR(b.right(), 1075, 1e-9);
  EXPECT_NEAR(b.top(), 500, 1e-9);
}

TEST(WidePolylineTest, APerVertexWidthTapers) {
  // 100 wide at the start to 0 at the end: a triangle of 1,000 x 100.
  const Contour c = swept_outline({{0, 0, 0, 100, 0}, {1000, 0, 0, 0, 0}}, 0.05);
  EXPECT_NEAR(contour_area(c), 50000, 1e-6);
}

TEST(WidePolylineTest, AnArcIsABandOfItsWidth) {
  // A half turn of radius 1,000, 200 wide: half an annulus between 900 and 1,100.
  const Contour c = swept_outline({{1000, 0, 1, 200, 200}, {-1000, 0, 0, 0, 0}}, 0.01);
  const double half_annulus = 3.14159265358979323846 * (1100.0 * 1100 - 900.0 * 900) / 2;
  EXPECT_NEAR(contour_area(c), half_annulus, half_annulus * 1e-4);
}

TEST(WidePolylineTest, ASharpTurnIsBevelledNotSpiked) {
  // A hairpin: a mitre would reach far beyond the band.
  const Contour c =
      swept_outline({{0, 0, 0, 100, 100}, {1000, 0, 0, 100, 100}, {0, 10, 0, 0, 0}}, 0.05);
  EXPECT_LT(contour_bounds(c).right(), 1000 + 4 * 50 + 1e-9);
}

TEST(WidePolylineTest, NoWidthCoversNothing) {
  EXPECT_TRUE(swept_outline({{0, 0, 0, 0, 0}, {1000, 0, 0, 0, 0}}, 0.05).empty());
  EXPECT_TRUE(swept_outline({{0, 0, 0, 100, 100}}, 0.05).empty());
}

}  // namespace
}  // namespace curdle::site
