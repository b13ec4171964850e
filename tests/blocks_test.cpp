// Tests of blocks.h.
#include "kinds/blocks.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
using test::design;

TEST(Blocks, PlanAndElevationShowTheFirstBlockSeen) {
  const Design d = test::design(2, 3, {{"7/8", "3/4", "3/4"}, {"3/4", "1/2", "3/4"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("blocks"));
  spec.module_w = spec.module_h = 6000, spec.own<BlocksKeys>().voxel_h = 3000;
  const CurdField f = curdle(d, 3, d.field);
  const Layout layout = make_layout(d, f, d.field, spec);
  const auto counts = value_counts(f);
  EXPECT_EQ(layout.elements.size(), 512 - counts[0]);
  std::map<std::pair<double, double>, uint32_t> shown;
  std::multiset<std::string> in_plan;  // every block named once, under its plan cell
  for (const BlockViews::Cell& v : layout.block_views->cells) {
    shown[{v.rect.x, v.rect.y}] = v.value;
    if (v.plan) in_plan.insert(v.elements.begin(), v.elements.end());
  }
  std::multiset<std::string> ids;
  for (const Element& e : layout.elements) ids.insert(e.id);
  EXPECT_EQ(in_plan, ids);
  for (int64_t x = 0; x < 8; ++x) {
    for (int64_t y = 0; y < 8; ++y) {  // plan: the top-most block
      uint32_t top = 0;
      for (int64_t z = 0; z < 8; ++z)
        if (const uint32_t v = f.value_at({x, y, z})) top = v;
      const auto it = shown.find({x * 6000.0, y * 6000.0});
      EXPECT_EQ(it == shown.end() ? 0u : it->second, top) << x << "," << y;
    }
    for (int64_t z = 0; z < 8; ++z) {  // elevation: the first block from the front
      uint32_t first = 0;
      for (int64_t y = 7; y >= 0; --y)
        if (const uint32_t v = f.value_at({x, y, z})) first = v;
      const auto it = shown.find({48000 + 12000 + x * 6000.0, z * 3000.0});
      EXPECT_EQ(it == shown.end() ? 0u : it->second, first) << x << "," << z;
    }
  }
  SvgSummary svg = parse_svg(svg_of(layout));
  for (uint32_t v = 1; v < 4; ++v)
    EXPECT_EQ(svg.counts[v], 0u);  // views are drawings, not elements
}

}  // namespace curdle
