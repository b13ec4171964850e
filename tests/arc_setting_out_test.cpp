#include "layout/arc_setting_out.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(ArcSettingOutTest, ArcsByCentreRadiusAndEnds) {
  Layout layout;
  layout.width = 14000, layout.height = 9000;
  layout.outline_contour = {{0, 0, 0}, {14000, 0, 0}, {14000, 9000, -0.2}, {4000, 9000, 0}};
  ZoneCount pit;
  pit.name = "tree pit";
  pit.contour = {{4300, 4000, 1}, {5700, 4000, 1}};
  layout.zones.push_back(pit);
  const auto arcs = arcs_to_set_out(layout);
  ASSERT_EQ(arcs.size(), 2u);
  EXPECT_EQ(arcs[0].line,
            "A1: arc, centre (9000, 21000), radius 13000, from (14000, 9000) to (4000, 9000)");
  EXPECT_TRUE(arcs[1].circle);
  EXPECT_EQ(arcs[1].line, "tree pit: circle, centre (5000, 4000), radius 700");
  // The outline is set out by its corners, not its chords; the arc's centre is off the surface.
  EXPECT_EQ(set_out_points(layout.outline_contour, 14000, 9000).size(), 4u);
  EXPECT_EQ(set_out_points(pit.contour, 14000, 9000).size(), 4u);  // two ends, the centre twice
}

}  // namespace
}  // namespace curdle
