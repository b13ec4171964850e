// Tests of rhythm.h.
#include "kinds/rhythm.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "building_support.h"
#include "layout/contour.h"
#include "layout/framed_boxes.h"
#include "layout_support.h"

namespace curdle {
using test::design;

TEST(Rhythm, FinWidthsFollowTheValuesCentredInTheirBays) {
  const Design d = test::design(4, 1, {{"3/4", "3/4", "2/3"}, {"1/2", "3/4", "3/4"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("rhythm"));
  spec.module_w = 600, spec.module_h = 4200;
  spec.own<RhythmKeys>().widths = {0, 100, 180, 300};
  const CurdField f = curdle(d, 64, d.field);
  const Layout layout = make_layout(d, f, d.field, spec);
  const auto counts = value_counts(f);
  EXPECT_EQ(layout.elements.size(), 64 - counts[0]);
  for (uint32_t v = 0; v < 4; ++v) EXPECT_EQ(layout.legend[v].count, counts[v]);
  for (const Element& e : layout.elements) {
    EXPECT_EQ(e.value, f.value_at({e.cell_x, 0, 0}));
    EXPECT_NEAR(e.shape[0].w, spec.own<RhythmKeys>().widths[e.value], 1e-9);
    EXPECT_NEAR(e.shape[0].x + e.shape[0].w / 2, e.cell_x * 600 + 300, 1e-9);
    EXPECT_NEAR(e.shape[0].h, 4200, 1e-9);
  }
  SvgSummary svg = parse_svg(svg_of(layout));
  for (uint32_t v = 0; v < 4; ++v)
    EXPECT_EQ(svg.counts[v], v ? counts[v] : 0u) << "fins of value " << v;
}

// Fins round a building: each on one face, standing off it by the kind's thickness, square to
// it (along the radius on an arc); a fin whose bay would turn a corner is left out, and said.
TEST(Rhythm, FinsStandOffEachFaceOfABuildingSquareToIt) {
  const Layout l = test::lay_recipe(R"(name = "fins"
seed = 64
[lattice]
base = 4
dimension = 1
[[curds]]
probabilities = ["1", "1", "1"]
[layout]
kind = "rhythm"
bay = 600
widths = [0, 200]
[layout.building]
plan = [[0, 0], [12000, 0, 0.25], [12000, 8000], [0, 8000]]
height = 4200
)");
  ASSERT_EQ(l.frames().size(), 4u);
  ASSERT_FALSE(l.elements.empty());
  const double radius = frame_radius(l.frames()[1]);
  size_t on_arc = 0;
  for (const Element& e : l.elements) {
    const Rect& r = e.shape.front();
    const SurfaceFrame* f = frame_at(l.frames(), r.x + r.w / 2);
    EXPECT_GE(r.x, f->start - 1e-9) << e.id;  // on one face
    EXPECT_LE(r.right(), f->start + f->length + 1e-9) << e.id;
    EXPECT_NEAR(r.h, 4200, 1e-9);
    const std::array<double, 2> depth = framed_depth(l, e);
    EXPECT_EQ(depth[0], -300) << e.id;  // off the face, in front of it
    EXPECT_EQ(depth[1], 0) << e.id;
    const BuildingPoint c = framed_centre(l, e);  // its outer edge, 300 mm off the face
    if (f == &l.frames()[1]) {
      ++on_arc;
      const Arc arc = arc_between({f->from[0], f->from[1], f->bulge}, {f->to[0], f->to[1], 0});
      // A straight plate square to the chord across its bay's part of the face: its outer
      // edge's middle 300 mm off that chord's middle, along the radius.
      const double half = r.w / 2;
      EXPECT_NEAR(std::hypot(c[0] - arc.centre[0], c[1] - arc.centre[1]),
                  std::sqrt(radius * radius - half * half) + 300, 1e-3);  // chord, not arc
    } else if (f == &l.frames()[0]) {
      EXPECT_NEAR(c[1], -300, 1e-9);  // the south face: off it towards the south
    }
  }
  EXPECT_GT(on_arc, 5u);
  // Every bay has a fin (every cell survives): those 200 mm wide round a bay's middle that
  // would cross a corner, or run past the strip's end, are the ones left out.
  const auto bays = static_cast<size_t>(std::ceil(l.width / 600 - 1e-9));
  size_t turning = 0;
  for (size_t k = 0; k < bays; ++k) {
    const double from = 600.0 * static_cast<double>(k) + 200, to = from + 200;
    bool crosses = to > l.width + 1e-9;
    for (const SurfaceFrame& f : l.frames())
      crosses = crosses || (from < f.start + f.length - 1e-9 && to > f.start + f.length + 1e-9);
    turning += crosses;
  }
  ASSERT_GT(turning, 0u);
  EXPECT_EQ(l.elements.size(), bays - turning);
  EXPECT_NE(
      std::find(l.notes.begin(), l.notes.end(),
                fmt::format("{} fin{} at a corner (or past the end) left out: a fin stands "
                            "on one face",
                            turning, turning == 1 ? " that would turn" : "s that would turn")),
      l.notes.end());
}

}  // namespace curdle
