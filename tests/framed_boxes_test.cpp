// Tests of framed_boxes.h: a unit of the pavilion's strip in 3-D, along its façade and turned
// round a corner in one box a face; a unit of a curved wall a chord of its arc; and the middle
// of a unit's face, the position the schedule gives.
#include "layout/framed_boxes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "building_support.h"
#include "layout/piece_rows.h"

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
  l.envelope.emplace().frames = {arc};
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

TEST(FramedBoxes, AUnitBentToAnArcIsFacetsWithinAQuarterMillimetreOfIt) {
  Layout l;
  SurfaceFrame arc;  // a quarter circle of 12 m radius, its units bent to it
  arc.from = {12000, 0};
  arc.to = {0, 12000};
  arc.bulge = std::tan(3.14159265358979323846 / 8);
  arc.length = 12000 * 3.14159265358979323846 / 2;
  arc.bent = true;
  l.envelope.emplace().frames = {arc};
  l.width = arc.length;
  const std::vector<FramedBox> b = framed_boxes(l, Rect{1000, 0, 1200, 600}, 0, 20);
  ASSERT_GE(b.size(), 2u);
  double length = 0;
  for (const FramedBox& f : b) {
    length += f.length;
    // Each facet's outer face ends on the arc and rises at most 0.25 mm from it.
    const double middle = std::hypot(f.centre[0] + f.along[1] * 10, f.centre[1] - f.along[0] * 10);
    EXPECT_GE(middle, 12000 - 0.25 - 1e-9);
    EXPECT_NEAR(std::hypot(middle, f.length / 2), 12000, 1e-6);
  }
  EXPECT_NEAR(length, 1200, 0.01);  // the developed width, within 10 µm
  Element e;
  e.nominal = Rect{1000, 0, 1200, 600};
  e.shape = {e.nominal};
  const BuildingPoint p = framed_centre(l, e);
  EXPECT_GE(std::hypot(p[0], p[1]), 12000 - 0.25 - 1e-9);
  EXPECT_LE(std::hypot(p[0], p[1]), 12000 + 1e-9);
}

TEST(FramedBoxes, UnitsBentToACurvedFacadeAreOrderedOnTheirOwnLine) {
  const Layout l = test::lay_recipe(test::building_recipe(
      "panel = [1200, 600]\njoint = 12\nbond = \"stack\"\n",
      "plan = [[0, 0, 0.2], [14000, 0], [14000, 8000], [0, 8000]]\nheight = 1224\ndepth = 20\n"
      "arcs = \"bent\"\n"));
  ASSERT_TRUE(l.frames()[0].bent);
  size_t bent = 0;
  for (const Element& e : l.elements) {
    const std::string type = element_type_of(l, e);
    if (type.find("bent to a 18200 mm radius") == std::string::npos) continue;
    ++bent;
    EXPECT_EQ(framed_facade(l, e)->name, "S");
    if (!e.cut) {
      EXPECT_NEAR(e.nominal.w, 1200, 1e-9);  // as ordered: its developed width
    }
  }
  EXPECT_GT(bent, 20u);
}

}  // namespace
}  // namespace curdle
