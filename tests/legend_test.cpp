// Tests of legend.h.
#include "layout/legend.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
using test::design;

// Two values laid in the same product (the darkest where both curds survive, as the second
// curd) are one line of the legend, of the sheets' keys and of the hatches, as quantities.csv
// has them; they were two lines with the same name.
TEST(Legend, ValuesOfOneProductAreOneLine) {
  Design d = design(4, 2, {{"3/4", "3/4"}, {"3/4", "3/4"}});
  const CurdField f = curdle(d, 2, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.module_w = spec.module_h = 100;
  spec.value_colours = {Rgb{230, 230, 220}, Rgb{140, 140, 130}, Rgb{60, 60, 60}, Rgb{60, 60, 60}};
  spec.materials = {"Buff", "Grey", "Black", "Black"};
  const Layout layout = make_layout(d, f, d.field, spec);
  EXPECT_EQ(layout.legend[3].same_as, 2u);
  EXPECT_EQ(layout.legend[1].same_as, 1u);
  const std::vector<LegendLine> lines = legend_lines(layout.legend);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[2].values, "2, 3");
  EXPECT_EQ(lines[2].count, layout.legend[2].count + layout.legend[3].count);
  // The same label in another colour is another product.
  spec.value_colours[3] = Rgb{20, 20, 20};
  EXPECT_EQ(make_layout(d, f, d.field, spec).legend[3].same_as, 3u);
}

}  // namespace curdle
