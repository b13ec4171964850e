// Tests of ground_colour.h.
#include "layout/ground_colour.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {

// The joints' colour where there are joints; with none, the most common value's (its seams
// vanish); kept curds and parks on white; a perforated sheet's metal under its openings.
TEST(GroundColour, JointsTheCommonestValueWhiteOrMetal) {
  const Design d = test::design(4, 2, {{"1/2", "1/2"}});
  LayoutSpec spec = test::layout_spec();
  spec.value_colours = {Rgb{200, 190, 180}, Rgb{40, 40, 40}};
  Layout layout = make_layout(d, curdle(d, 3, d.field), d.field, spec);
  ASSERT_GT(layout.legend[0].count, layout.legend[1].count);  // 3 in 4 cells die
  EXPECT_EQ(ground_colour(layout), (Rgb{200, 190, 180}));
  layout.joint = 5, layout.joint_colour = Rgb{9, 9, 9};
  EXPECT_EQ(ground_colour(layout), (Rgb{9, 9, 9}));
  layout.joint = 0, layout.combine = Combine::keep;
  EXPECT_EQ(ground_colour(layout), (Rgb{255, 255, 255}));
  LayoutSpec park = test::trees_and_benches();
  EXPECT_EQ(ground_colour(make_layout(d, curdle(d, 3, d.field), d.field, park)),
            (Rgb{255, 255, 255}));
  LayoutSpec screen = test::layout_spec();
  screen.set_kind(layout_kind("perforation"));
  screen.module_w = screen.module_h = 40;
  screen.own<PerforationKeys>().thickness = 2;
  screen.own<PerforationKeys>().holes = {{16, 0, 0}};
  EXPECT_EQ(ground_colour(make_layout(d, curdle(d, 3, d.field), d.field, screen)), kSheetMetal);
}

}  // namespace curdle
