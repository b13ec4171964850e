// Tests of joint_area.h: the joints of small grids worked out by hand.
#include "layout/joint_area.h"

#include <gtest/gtest.h>

#include "layout/builder.h"
#include "layout_support.h"

namespace curdle {
namespace {

// Three columns and two rows of 300 mm tiles with 10 mm joints on a floor of exactly
// 920 x 610 mm, with `zones` on it.
Layout small_floor(std::vector<Zone> zones = {}, double bond = 0, double joint = 10) {
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.module_w = spec.module_h = 300, spec.joint = joint;
  spec.size = std::array<double, 2>{920, 610};
  spec.bond = bond;
  spec.zones = std::move(zones);
  return lay_floor(test::design(2, 2, {{"1/2"}}), spec, 3);
}

double elements_area(const Layout& layout) {
  double area = 0;
  for (const Element& e : layout.elements) area += e.area();
  return area;
}

TEST(JointArea, AGridsJointsCountTheirCrossingsOnce) {
  const Layout layout = small_floor();
  ASSERT_EQ(layout.elements.size(), 6u);
  // Two vertical joints of 10 x 610, one horizontal of 920 x 10, crossing twice in 10 x 10.
  EXPECT_NEAR(joint_area(layout), 2 * 10 * 610 + 920 * 10 - 2 * 10 * 10, 1e-9);
  EXPECT_NEAR(elements_area(layout) + joint_area(layout), 920.0 * 610, 1e-9);
}

TEST(JointArea, AnOpeningTakesTheJointsItCovers) {
  // The middle column's two tiles and the 300 mm of horizontal joint between them.
  const Polygon middle = {{310, 0}, {610, 0}, {610, 610}, {310, 610}};
  const Layout layout =
      small_floor({{"opening", ZoneRule::exclude, 0, middle, *as_rectangles(middle)}});
  EXPECT_EQ(layout.elements.size(), 4u);
  EXPECT_NEAR(joint_area(layout), 2 * 10 * 610 + 920 * 10 - 2 * 10 * 10 - 300 * 10, 1e-9);
}

TEST(JointArea, ABondsCoursesEachKeepTheirOwnVerticalJoints) {
  const Layout bonded = small_floor({}, 0.5);
  EXPECT_NEAR(elements_area(bonded) + joint_area(bonded), 920.0 * 610, 1e-6);
  EXPECT_GT(joint_area(bonded), 0);
}

TEST(JointArea, NoJointNoArea) { EXPECT_EQ(joint_area(small_floor({}, 0, 0)), 0); }

}  // namespace
}  // namespace curdle
