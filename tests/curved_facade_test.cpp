// Tests of curved_facade.h: the garden wall's arc as sheet 1 sets it out (centre, radius, ends,
// the offsets from its chord) and how its bricks sit on it.
#include "layout/curved_facade.h"

#include <gtest/gtest.h>

#include <cmath>

#include "building_support.h"

namespace curdle {
namespace {

TEST(CurvedFacade, TheGardenWallIsSetOutByCentreRadiusEndsAndChordOffsets) {
  const Layout l = test::lay_recipe(test::building_recipe(
      "panel = [215, 65]\njoint = 10\n",
      "path = [[0, 0], { centre = [0, 12000], length = 18000 }, [14000, 6000]]\nheight = 600\n"));
  const std::vector<CurvedFacade> arcs = curved_facades(l);
  ASSERT_EQ(arcs.size(), 1u);  // the straight return is not curved
  const CurvedFacade& c = arcs[0];
  EXPECT_NEAR(c.radius, 12000, 1e-6);
  EXPECT_NEAR(c.centre[0], 0, 1e-6);
  EXPECT_NEAR(c.centre[1], 12000, 1e-6);
  EXPECT_NEAR(c.sweep, 1.5 * 180 / M_PI, 1e-9);
  EXPECT_NEAR(c.chord, 2 * 12000 * std::sin(0.75), 1e-6);
  EXPECT_TRUE(c.convex);
  EXPECT_NEAR(c.inside, 12000 - std::sqrt(12000.0 * 12000 - 215.0 * 215 / 4), 1e-9);
  EXPECT_NEAR(c.joint_back, 8.1, 0.05);
  // Stations 2 m apart on a 16.36 m chord: 0 to 16 m and the far end; the middle one rises
  // nearly the arc's whole sagitta, the ends none.
  ASSERT_EQ(c.offsets.size(), 10u);
  EXPECT_DOUBLE_EQ(c.offsets[1].along, 2000);
  EXPECT_NEAR(c.offsets.front().offset, 0, 1e-6);
  EXPECT_NEAR(c.offsets.back().offset, 0, 1e-6);
  EXPECT_NEAR(c.offsets.back().along, c.chord, 1e-9);
  const double sagitta = 12000 * (1 - std::cos(0.75));
  EXPECT_NEAR(c.offsets[4].offset,
              std::sqrt(12000.0 * 12000 - std::pow(8000 - c.chord / 2, 2)) - 12000 * std::cos(0.75),
              1e-6);
  EXPECT_LT(c.offsets[4].offset, sagitta);
  EXPECT_NE(c.line.find("radius 12000 mm at the face, centre (0, 12000), from (0, 0)"),
            std::string::npos)
      << c.line;
  EXPECT_NE(c.units.find("each joint 10 mm at the face, 8.1 mm at the back"), std::string::npos)
      << c.units;
  EXPECT_EQ(c.brief[0], "façade SE: radius 12000 mm round centre (0, 12000)");
  EXPECT_EQ(c.brief[1], "chord 215 mm a unit; joints 10 mm face, 8.1 mm back");
}

TEST(CurvedFacade, AScreensSheetsAreRolledToTheArc) {
  const Layout l = test::lay_recipe(test::screen_recipe());
  const std::vector<CurvedFacade> arcs = curved_facades(l);
  ASSERT_EQ(arcs.size(), 1u);
  EXPECT_EQ(arcs[0].brief[1], "sheets rolled to it, 7997.0 mm inside radius");
  EXPECT_NE(arcs[0].units.find("sheets rolled to the arc, 7997.0 mm inside radius"),
            std::string::npos);
}

}  // namespace
}  // namespace curdle
