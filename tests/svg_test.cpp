// Tests of svg.h.
#include "export/drawing/svg.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
using test::design;

TEST(Layout, MixBlendsOrTakesTheGivenColoursAndKeepShowsEachCurd) {
  Design d = design(4, 2, {{"3/4", "3/4"}, {"3/4", "3/4"}});
  d.curds[0].colour = Rgb{200, 0, 0};
  d.curds[1].colour = Rgb{0, 0, 200};
  const CurdField f = curdle(d, 2, d.field);
  LayoutSpec mix = test::layout_spec();
  mix.module_w = mix.module_h = 100;
  const Layout mixed = make_layout(d, f, d.field, mix);
  EXPECT_EQ(mixed.legend[3].colour, (Rgb{100, 0, 100}));  // red and blue give purple
  mix.value_colours = {Rgb{1, 1, 1}, std::nullopt, Rgb{3, 3, 3}, Rgb{4, 4, 4}};
  const Layout given = make_layout(d, f, d.field, mix);
  EXPECT_EQ(given.legend[3].colour, (Rgb{4, 4, 4}));
  EXPECT_EQ(given.legend[1].colour, (Rgb{200, 0, 0}));
  EXPECT_EQ(parse_svg(svg_of(given)).fills[3], "#040404");

  LayoutSpec keep = mix;
  keep.combine = Combine::keep;
  keep.value_colours.clear();
  const Layout kept = make_layout(d, f, d.field, keep);
  ASSERT_EQ(kept.legend[3].parts.size(), 2u);
  EXPECT_EQ(kept.legend[3].parts[0], (Rgb{200, 0, 0}));
  EXPECT_EQ(kept.legend[3].parts[1], (Rgb{0, 0, 200}));
  SvgSummary svg = parse_svg(svg_of(kept));
  EXPECT_EQ(svg.patterns, 4);
  EXPECT_EQ(svg.fills[3], "url(#parts-3)");
  // The PNG shows both curds in a cell of value 3: red on the left, blue on the right.
  Layout drawn = kept;
  drawn.drawing.scale = 1, drawn.drawing.dpi = 25.4;  // one pixel per millimetre
  const PreviewImage png = render_layout(drawn);
  for (const Element& e : kept.elements) {
    if (e.value != 3) continue;
    auto at = [&](double x, double y) {
      const size_t px = static_cast<size_t>(x), py = static_cast<size_t>(kept.height - y);
      const uint8_t* p = &png.rgb[(py * png.width + px) * 3];
      return Rgb{p[0], p[1], p[2]};
    };
    EXPECT_EQ(at(e.nominal.x + 20, e.nominal.y + 50), (Rgb{200, 0, 0}));
    EXPECT_EQ(at(e.nominal.x + 80, e.nominal.y + 50), (Rgb{0, 0, 200}));
    break;
  }
}

TEST(Layout, OverlaysDrawTheStageGridInTheJointsAndTheWindow) {
  const Design d = design(4, 2, {{"3/4", "2/3"}});
  const CurdField f = curdle(d, 8, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.joint = 10;
  spec.drawing.stage_grid = true;
  spec.drawing.highlight = Box{{4, 4, 0}, {8, 4, 1}};
  const Layout layout = make_layout(d, f, d.field, spec);
  // The stage-1 boundary between cells 3 and 4 runs in the middle of their joint.
  EXPECT_NEAR(layout.cell_edge_x(4), 4 * 310 - 5, 1e-9);
  EXPECT_NEAR(layout.cell_edge_x(0), 0, 1e-9);
  EXPECT_NEAR(layout.cell_edge_x(16), layout.width, 1e-9);
  const std::string svg = svg_of(layout);
  const SvgSummary s = parse_svg(svg);
  EXPECT_TRUE(s.ids.count("stage-grid"));
  EXPECT_TRUE(s.ids.count("window"));
  EXPECT_NE(svg.find("data-cells=\"4,4,8,4\""), std::string::npos);
  EXPECT_TRUE(s.classes.count("stage-0") && s.classes.count("stage-1"));
}

TEST(Layout, ALargePavingStaysSmallAsSvg) {
  Design d = design(2, 2, {std::vector<std::string>(10, "0.9")});
  d.field.size = {400, 600, 1};
  const CurdField f = curdle(d, 1, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.joint = 3;
  const Layout layout = make_layout(d, f, d.field, spec);
  const std::string svg = svg_of(layout);
  EXPECT_LT(svg.size(), (60u << 20) / 1000000 * 240000) << "240,000 tiles";
  SvgSummary s = parse_svg(svg);
  EXPECT_EQ(s.counts[0] + s.counts[1], 240000u);
}

}  // namespace curdle

namespace curdle {

// Two values laid in the same product are one line of layout.svg's legend (legend_test.cpp);
// they were two lines with the same name.
TEST(Layout, ValuesOfOneProductAreOneLineWhereverTheyAreListed) {
  Design d = design(4, 2, {{"3/4", "3/4"}, {"3/4", "3/4"}});
  const CurdField f = curdle(d, 2, d.field);
  const LayoutSpec spec = test::two_values_one_product();
  const Layout layout = make_layout(d, f, d.field, spec);
  const std::string svg = svg_of(layout);
  EXPECT_NE(svg.find(">2, 3 Black: "), std::string::npos);
  EXPECT_EQ(svg.find(">3 Black: "), std::string::npos);
}

}  // namespace curdle
