// Tests of framed_boxes.h: a unit of the pavilion's strip in 3-D, along its façade and turned
// round a corner in one box a face; a unit of a curved wall a chord of its arc; and the middle
// of a unit's face, the position the schedule gives.
#include "export/framed_boxes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "building_support.h"

namespace curdle {
namespace {

TEST(FramedBoxes, ACornerUnitIsABoxOnEachFaceMeetingAtTheCorner) {
  const Layout l = test::lay_recipe(test::pavilion_recipe());
  const Element* quoin = nullptr;
  for (const Element& e : l.elements)
    if (e.corner == 0 && e.row == 0) quoin = &e;
  ASSERT_NE(quoin, nullptr);
  const std::vector<FramedBox> boxes = framed_boxes(l, quoin->shape[0], 0, l.thickness);
  ASSERT_EQ(boxes.size(), 2u);
  // Course 0, corner 0: the stretcher on the south face up to the corner at (20000, 0), and
  // its end, a header of 102.5 mm, on the east face.
  EXPECT_NEAR(boxes[0].length, 215, 1e-9);
  EXPECT_NEAR(boxes[0].centre[0], 20000 - 215.0 / 2, 1e-9);
  EXPECT_NEAR(boxes[0].centre[1], 102.5 / 2, 1e-9);
  EXPECT_NEAR(boxes[1].length, 102.5, 1e-9);
  EXPECT_NEAR(boxes[1].along[1], 1, 1e-12);  // the east face runs north
  EXPECT_NEAR(boxes[1].centre[0], 20000 - 102.5 / 2, 1e-9);
  EXPECT_NEAR(boxes[1].centre[1], 102.5 / 2, 1e-9);
  EXPECT_NEAR(boxes[1].centre[2], 32.5, 1e-9);
  // Its position is the middle of its face round the corner: on the south face, 56.25 mm short.
  const BuildingPoint p = framed_centre(l, *quoin);
  EXPECT_NEAR(p[0], 20000 - 56.25, 1e-9);
  EXPECT_NEAR(p[1], 0, 1e-9);
  EXPECT_EQ(framed_facade(l, *quoin)->name, "S");
}

TEST(FramedBoxes, ACurvedWallsUnitsAreChordsOfItsArc) {
  Layout l;
  SurfaceFrame arc;  // a quarter circle of 12 m radius
  arc.from = {12000, 0};
  arc.to = {0, 12000};
  arc.bulge = std::tan(3.14159265358979323846 / 8);
  arc.length = 12000 * 3.14159265358979323846 / 2;
  l.frames = {arc};
  l.width = arc.length;
  const std::vector<FramedBox> b = framed_boxes(l, Rect{1000, 0, 215, 65}, 0, 100);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NEAR(b[0].length, 2 * 12000 * std::sin(215.0 / 2 / 12000), 1e-9);
  // Its outer face's chord lies inside the arc by the sagitta; the box's middle 50 mm further.
  const double half = 12000 * std::sin(215.0 / 2 / 12000);
  const double sagitta = 12000 - std::sqrt(12000.0 * 12000 - half * half);
  EXPECT_NEAR(std::hypot(b[0].centre[0], b[0].centre[1]), 12000 - sagitta - 50, 1e-6);
  const std::vector<FramedBox> long_one = framed_boxes(l, Rect{0, 0, 3000, 65}, 0, 100, 600);
  EXPECT_EQ(long_one.size(), 5u);
}

}  // namespace
}  // namespace curdle
