// Tests of perforation.h.
#include "kinds/perforation.h"

#include <gtest/gtest.h>

#include <map>

#include "layout/union.h"
#include "layout_support.h"

namespace curdle {
using test::design;

namespace {

struct Sheet {
  Design design;
  LayoutSpec spec = test::layout_spec();
  Layout layout;
};

Sheet perforated(Combine combine, HoleFix fix, double bridge, uint64_t seed) {
  Sheet s;
  s.design = test::design(4, 2, {{"1/2", "1/2"}, {"1/2", "1/2"}, {"1/2", "1/2"}});
  s.spec.set_kind(layout_kind("perforation"));
  s.spec.combine = combine;
  s.spec.module_w = s.spec.module_h = 40;
  s.spec.size = std::array<double, 2>{640, 640};
  s.spec.own<PerforationKeys>().thickness = 2;
  s.spec.own<PerforationKeys>().holes = {{16, -7, 6}, {16, 7, 6}, {16, 0, -7}};
  s.spec.own<PerforationKeys>().min_diameter = 5;
  s.spec.own<PerforationKeys>().min_bridge = bridge;
  s.spec.own<PerforationKeys>().edge_margin = 5;
  s.spec.own<PerforationKeys>().fix = fix;
  s.spec.own<PerforationKeys>().chord_tolerance = 0.01;
  const CurdField f = curdle(s.design, seed, s.design.field);
  s.layout = make_layout(s.design, f, s.design.field, s.spec);
  return s;
}

// Parts of an opening, for checking rules independently of the builder's own bookkeeping.
std::vector<Circle> circles_of(const Element& e, const LayoutSpec& spec) {
  if (e.circle) return {*e.circle};
  std::vector<Circle> parts;
  const double cx = e.nominal.x + e.nominal.w / 2, cy = e.nominal.y + e.nominal.h / 2;
  for (size_t c = 0; c < spec.own<PerforationKeys>().holes.size(); ++c)
    if (e.value >> c & 1)
      parts.push_back({cx + spec.own<PerforationKeys>().holes[c].offset_x,
                       cy + spec.own<PerforationKeys>().holes[c].offset_y,
                       spec.own<PerforationKeys>().holes[c].diameter});
  return parts;
}

}  // namespace

TEST(Perforation, AnOutlineBoundsTheOpeningsAndCutsTheSheets) {
  Sheet s;
  s.design = test::design(4, 2, {{"3/4", "3/4"}, {"1/2", "3/4"}});
  s.spec.set_kind(layout_kind("perforation"));
  s.spec.module_w = s.spec.module_h = 40;
  s.spec.size = std::array<double, 2>{640, 640};
  s.spec.outline = {{0, 0}, {640, 0}, {640, 400}, {320, 640}, {0, 400}};
  s.spec.own<PerforationKeys>().holes = {{16, 0, 0}, {24, 0, 0}};
  s.spec.own<PerforationKeys>().edge_margin = 5;
  s.spec.own<PerforationKeys>().fix = HoleFix::drop;
  s.spec.own<PerforationKeys>().sheet_size = std::array<double, 2>{320, 320};
  const Layout layout =
      make_layout(s.design, curdle(s.design, 3, s.design.field), s.design.field, s.spec);
  ASSERT_GT(layout.elements.size(), 50u);
  double open = 0;
  for (const Element& e : layout.elements) {
    const Circle& c = *e.circle;
    open += e.area();
    // At least the margin inside every edge of the outline.
    EXPECT_TRUE(contains(s.spec.outline, c.cx, c.cy)) << e.id;
    for (size_t i = 0; i < s.spec.outline.size(); ++i) {
      const auto& a = s.spec.outline[i];
      const auto& b = s.spec.outline[(i + 1) % s.spec.outline.size()];
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      const double t =
          std::clamp(((c.cx - a[0]) * dx + (c.cy - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      EXPECT_GE(std::hypot(a[0] + t * dx - c.cx, a[1] + t * dy - c.cy) - c.d / 2, 5 - 1e-9) << e.id;
    }
  }
  ASSERT_EQ(layout.sheets().size(), 4u);  // 2 x 2 sheets of 320, all meeting the gable
  double surface = 0;
  for (const auto& sheet : layout.sheets()) surface += sheet.surface;
  EXPECT_NEAR(surface, polygon_area(s.spec.outline), 1e-6);
  EXPECT_FALSE(layout.sheets()[2].outline.empty());  // the upper sheets follow the gable
  EXPECT_NEAR(layout.open_area, open / polygon_area(s.spec.outline), 1e-12);
}

TEST(Perforation, DroppingLeavesNoHoleTooCloseOrTooNearTheEdge) {
  for (Combine combine : {Combine::mix, Combine::keep})
    for (uint64_t seed = 1; seed <= 5; ++seed) {
      const Sheet s = perforated(combine, HoleFix::drop, 8, seed);
      const auto& holes = s.layout.elements;
      for (size_t i = 0; i < holes.size(); ++i) {
        const auto a = circles_of(holes[i], s.spec);
        for (const Circle& c : a) {
          EXPECT_GE(c.cx - c.d / 2, 5 - 1e-9);
          EXPECT_LE(c.cx + c.d / 2, 640 - 5 + 1e-9);
          EXPECT_GE(c.cy - c.d / 2, 5 - 1e-9);
          EXPECT_LE(c.cy + c.d / 2, 640 - 5 + 1e-9);
        }
        for (size_t j = i + 1; j < holes.size(); ++j)  // across cells too: every pair
          EXPECT_GE(bridge(a, circles_of(holes[j], s.spec)), 8 - 1e-9)
              << holes[i].id << " " << holes[j].id;
      }
      // Merged openings (mix) grow past their cell's spacing: an 8 mm bridge cannot hold
      // everywhere. Kept unions stay within 15 mm of the centre, 10 mm from any neighbour.
      if (combine == Combine::mix) {
        EXPECT_FALSE(s.layout.violations.empty());
      }
    }
}

TEST(Perforation, ReportingOnlyChangesNothing) {
  const Sheet report = perforated(Combine::mix, HoleFix::none, 8, 2);
  const Sheet none = perforated(Combine::mix, HoleFix::none, 0, 2);
  EXPECT_EQ(report.layout.elements.size(), none.layout.elements.size());
  EXPECT_GT(report.layout.violations.size(), 0u);
}

TEST(Perforation, MixMakesOneOpeningOfTheSummedAreaAndKeepCutsTheUnion) {
  const Sheet mix = perforated(Combine::mix, HoleFix::none, 0, 3);
  const Sheet keep = perforated(Combine::keep, HoleFix::none, 0, 3);
  const double one = Circle{0, 0, 16}.area();
  for (const Element& e : mix.layout.elements) {
    ASSERT_TRUE(e.circle);
    EXPECT_NEAR(e.area(), one * std::popcount(e.value), 1e-6) << e.id;  // all three overlap
  }
  bool merged = false;
  for (const Element& e : keep.layout.elements) {
    if (std::popcount(e.value) < 2) continue;
    ASSERT_TRUE(e.outline) << e.id;
    merged = true;
    EXPECT_LT(e.area(), one * std::popcount(e.value));  // the overlap counts once
    EXPECT_GT(e.area(), one * 1.2);
  }
  EXPECT_TRUE(merged);
  // The union is worked out once per set of curds and moved to each cell: every opening of a
  // value has the same outline from its cell's centre, and the area CGAL gives for it there.
  std::map<uint32_t, const Element*> first;
  for (const Element& e : keep.layout.elements) {
    if (!e.outline) continue;
    const Element* f = first.emplace(e.value, &e).first->second;
    const double dx = e.nominal.x - f->nominal.x, dy = e.nominal.y - f->nominal.y;
    ASSERT_EQ(e.outline->rings.size(), f->outline->rings.size()) << e.id;
    for (size_t r = 0; r < e.outline->rings.size(); ++r) {
      ASSERT_EQ(e.outline->rings[r].size(), f->outline->rings[r].size()) << e.id;
      for (size_t i = 0; i < e.outline->rings[r].size(); ++i) {
        EXPECT_NEAR(e.outline->rings[r][i][0], f->outline->rings[r][i][0] + dx, 1e-6) << e.id;
        EXPECT_NEAR(e.outline->rings[r][i][1], f->outline->rings[r][i][1] + dy, 1e-6) << e.id;
      }
    }
    EXPECT_NEAR(e.area(), union_of_circles(circles_of(e, keep.spec), 0.01).front().area, 1e-6)
        << e.id;
  }
  EXPECT_GT(first.size(), 1u);
  // Nothing dropped, one opening a cell: the legend's openings are the cells of each value;
  // the bare sheet (value 0) is drawn, not counted.
  const auto counts = value_counts(curdle(mix.design, 3, mix.design.field));
  for (uint32_t v = 1; v < 8; ++v) EXPECT_EQ(mix.layout.legend[v].count, counts[v]);
  EXPECT_EQ(mix.layout.legend[0].count, 0u);
}

TEST(Perforation, OpenAreaAgreesWithThePixelsOfTheDrawing) {
  for (Combine combine : {Combine::mix, Combine::keep}) {
    Sheet s = perforated(combine, HoleFix::drop, 2, 4);
    s.layout.drawing.scale = 1, s.layout.drawing.dpi = 127;  // 5 px a millimetre
    const PreviewImage png = render_layout(s.layout);
    const Rgb metal{201, 205, 210};
    double open = 0;
    for (size_t p = 0; p < png.rgb.size(); p += 3) {
      // Antialiased edges count by how far they are from the metal towards the hole colour.
      const double d = std::abs(png.rgb[p] - metal.r) + std::abs(png.rgb[p + 1] - metal.g) +
                       std::abs(png.rgb[p + 2] - metal.b);
      open += d > 0 ? 1 : 0;
    }
    const double pixels = static_cast<double>(png.width) * png.height;
    EXPECT_NEAR(open / pixels, s.layout.open_area, 0.004) << static_cast<int>(combine);
  }
}

}  // namespace curdle

#include <sstream>

#include "export/schedules/schedule.h"

namespace curdle {

// What is punched is counted as punched: the legend counts the openings laid per value (it
// counted cells, holes dropped by the rules and merged ones included: "2,082 D16" where 1,938
// were punched), and quantities.csv gives one line per diameter, whichever curds cut it, with
// nothing to buy in packs.
TEST(Perforation, TheLegendAndQuantitiesCountWhatIsPunched) {
  const Sheet s = perforated(Combine::mix, HoleFix::drop, 8, 2);
  std::vector<uint64_t> laid(s.layout.legend.size(), 0);
  for (const Element& e : s.layout.elements) ++laid[e.value];
  for (const LegendEntry& e : s.layout.legend) {
    if (e.value != 0) {
      EXPECT_EQ(e.count, laid[e.value]) << e.value;
    }
  }
  std::ostringstream out;
  write_quantities_csv(out, s.layout);
  std::istringstream lines(out.str());
  std::string line;
  std::getline(lines, line);  // the header
  size_t d16 = 0;
  uint64_t d16_count = 0;
  while (std::getline(lines, line)) {
    std::vector<std::string> f;
    std::istringstream cells(line.substr(0, line.find('\r')) + ",");
    for (std::string cell; std::getline(cells, cell, ',');) f.push_back(cell);
    if (f.size() < 15 || f[3] != "D16") continue;
    ++d16;
    EXPECT_EQ(f[1], "c0 + c1 + c2");  // the curds whose holes are 16 mm
    EXPECT_EQ(f[13] + f[14], "");     // no pack size, no packs: nothing is bought
    d16_count = std::stoull(f[5]);
  }
  EXPECT_EQ(d16, 1u);
  EXPECT_EQ(d16_count, laid[1] + laid[2] + laid[4]);  // every single hole, in one line
}

}  // namespace curdle
