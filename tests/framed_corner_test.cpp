// Tests of framed_corner.h: a unit that turns a corner is one prism. At a square corner, outer
// or inner, it is the brick itself (215 x 102.5 mm in plan), not a box a face that overlap; at
// an obtuse and an acute corner its two faces reach along their façades and its backs meet at
// the mitre, so that its plan area is t (a + b) - t^2 tan(turn / 2); a corner too sharp for the
// unit is refused with the least angle that can be laid.
#include "layout/framed_corner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "building/coursing.h"
#include "building/facades.h"
#include "building_support.h"
#include "curdle/error.h"
#include "layout/contour.h"

namespace curdle {
namespace {

double area(const std::vector<std::array<double, 2>>& ring) {
  double a = 0;
  for (size_t k = 0; k < ring.size(); ++k) {
    const auto& p = ring[k];
    const auto& q = ring[(k + 1) % ring.size()];
    a += p[0] * q[1] - p[1] * q[0];
  }
  return a / 2;
}

double triangles_area(const std::vector<std::array<double, 2>>& ring) {
  double a = 0;
  for (const auto& t : footprint_triangles(ring)) a += area({ring[t[0]], ring[t[1]], ring[t[2]]});
  return a;
}

TEST(FramedCorner, ASquareCornersUnitIsTheBrickItselfOuterOrInner) {
  const Layout l = test::lay_recipe(test::pavilion_recipe());
  size_t corners = 0;
  for (const Element& e : l.elements) {
    if (e.corner < 0) continue;
    const auto p = framed_corner(l, e, l.thickness);
    ASSERT_TRUE(p) << e.id;
    ++corners;
    EXPECT_NEAR(area(p->footprint), 215 * 102.5, 1e-6) << e.id;
    EXPECT_NEAR(triangles_area(p->footprint), 215 * 102.5, 1e-6) << e.id;
    EXPECT_NEAR(p->height, 65, 1e-9);
    EXPECT_NEAR(p->base, 75.0 * static_cast<double>(e.row), 1e-9);
  }
  EXPECT_EQ(corners, 6u * 94);
  // Course 0 at the south-east corner: the stretcher along the south face up to (20000, 0);
  // course 1: the stretcher along the east face from it, the header on the south.
  for (const Element& e : l.elements) {
    if (e.corner != 0 || e.row > 1) continue;
    const auto p = framed_corner(l, e, l.thickness);
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const auto& v : p->footprint)
      x0 = std::min(x0, v[0]), x1 = std::max(x1, v[0]), y0 = std::min(y0, v[1]),
      y1 = std::max(y1, v[1]);
    EXPECT_NEAR(x1, 20000, 1e-9);
    EXPECT_NEAR(y0, 0, 1e-9);
    EXPECT_NEAR(x1 - x0, e.row == 0 ? 215 : 102.5, 1e-9) << e.id;
    EXPECT_NEAR(y1 - y0, e.row == 0 ? 102.5 : 215, 1e-9) << e.id;
  }
}

TEST(FramedCorner, AnObtuseAndAnAcuteCornerMeetAtTheArrisAndTheMitre) {
  // A trapezoid: 71.6° at (10000, 0), 108.4° at (8000, 6000).
  const Layout l = test::lay_recipe(test::building_recipe(
      "panel = [215, 65]\njoint = 10\n",
      "plan = [[0, 0], [10000, 0], [8000, 6000], [0, 6000]]\nheight = 750\n"));
  const double t = l.thickness;
  size_t seen = 0;
  for (const Element& e : l.elements) {
    if (e.corner < 0 || e.corner > 1) continue;
    const SurfaceFrame& f = l.frames()[static_cast<size_t>(e.corner)];
    const auto p = framed_corner(l, e, t);
    ASSERT_TRUE(p) << e.id;
    ++seen;
    const double at = f.start + f.length;
    const double a = at - e.nominal.x, b = e.nominal.right() - at;
    const double turn = f.turn_at_end * std::numbers::pi / 180;
    EXPECT_NEAR(area(p->footprint), t * (a + b) - t * t * std::tan(turn / 2), 1e-6) << e.id;
    EXPECT_NEAR(triangles_area(p->footprint), area(p->footprint), 1e-6) << e.id;
    // The arris is the plan's corner; at the acute one the header reaches the mitre.
    bool arris = false;
    for (const auto& v : p->footprint) arris |= std::hypot(v[0] - f.to[0], v[1] - f.to[1]) < 1e-6;
    EXPECT_TRUE(arris) << e.id;
    EXPECT_GE(std::min(a, b) + 1e-9, t * std::max(1.0, std::tan(turn / 2))) << e.id;
  }
  EXPECT_EQ(seen, 2u * 10);
}

TEST(FramedCorner, ACornerTooSharpForTheUnitIsRefusedWithTheLeastAngle) {
  const LayoutSpec spec = test::bricks();
  BuildingKeys keys;
  keys.plan = contour_of({{0, 0}, {10000, 0}, {0, 4000}});  // 21.8° at (10000, 0)
  keys.height = 750;
  try {
    check_corner_room(envelope_of(keys, spec), spec);
    ADD_FAILURE() << "a 21.8° corner was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "plan");
    EXPECT_NE(e.message().find("is 21.8°, too sharp for a 215 mm unit 102.5 mm deep to turn"),
              std::string::npos)
        << e.message();
    EXPECT_NE(e.message().find("corners of at least 51.0° can be laid"), std::string::npos)
        << e.message();
  }
}

}  // namespace
}  // namespace curdle
