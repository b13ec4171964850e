// The drawing scale: the recipe's, else the smallest standard scale that fits the sheet; known
// from the spec before the layout is built.
#include "layout/drawing_scale.h"

#include <gtest/gtest.h>

#include "curdle/curdling.h"
#include "layout/builder.h"
#include "test_support.h"

namespace curdle {
namespace {

TEST(DrawingScale, TheSmallestStandardScaleThatFitsTheSheet) {
  const Design d = test::design(4, 2, {{"3/4", "2/3"}});
  const CurdField f = curdle(d, 8, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.joint = 20;
  Layout layout = make_layout(d, f, d.field, spec);
  EXPECT_EQ(drawing_scale(layout), 20);  // 5.1 m fits an A3 sheet at 1:20, not at 1:10
  layout.drawing.paper = "A1";
  EXPECT_EQ(drawing_scale(layout), 10);
  layout.drawing.scale = 25;
  EXPECT_EQ(drawing_scale(layout), 25) << "the recipe's scale is kept";
}

TEST(DrawingScale, TheExtentIsKnownBeforeTheLayoutIsBuilt) {
  const Design d = test::design(4, 2, {{"3/4", "2/3"}});
  const CurdField f = curdle(d, 8, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.joint = 20;
  const Layout built = make_layout(d, f, d.field, spec);
  const Layout extent = layout_extent(spec, d.field);
  // The grid's pitches: the built layout leaves out the last joint.
  EXPECT_NEAR(extent.width, built.width, spec.joint);
  EXPECT_NEAR(extent.height, built.height, spec.joint);
  EXPECT_EQ(drawing_scale(extent), drawing_scale(built));
  EXPECT_TRUE(extent.elements.empty());
}

}  // namespace
}  // namespace curdle
