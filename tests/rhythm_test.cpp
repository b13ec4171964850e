// Tests of rhythm.h.
#include "kinds/rhythm.h"

#include <gtest/gtest.h>

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

}  // namespace curdle
