// Tests of legend.h.
#include "layout/legend.h"

#include <gtest/gtest.h>

#include <map>

#include "kinds/park.h"
#include "layout_support.h"

namespace curdle {
using test::design;

// Two values laid in the same product (the darkest where both curds survive, as the second
// curd) are one line of the legend, of the sheets' keys and of the hatches, as quantities.csv
// has them; they were two lines with the same name.
TEST(Legend, ValuesOfOneProductAreOneLine) {
  Design d = design(4, 2, {{"3/4", "3/4"}, {"3/4", "3/4"}});
  const CurdField f = curdle(d, 2, d.field);
  LayoutSpec spec = test::two_values_one_product();
  const Layout layout = make_layout(d, f, d.field, spec);
  EXPECT_EQ(layout.legend[3].same_as, 2u);
  EXPECT_EQ(layout.legend[1].same_as, 1u);
  const std::vector<LegendLine> lines = legend_lines(layout.legend);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[2].values, "2, 3");
  EXPECT_EQ(lines[2].count, layout.legend[2].count + layout.legend[3].count);
  EXPECT_EQ(lines[2].looks.size(), 1u);
  // The same label in another colour is another product.
  spec.value_colours[3] = Rgb{20, 20, 20};
  EXPECT_EQ(make_layout(d, f, d.field, spec).legend[3].same_as, 3u);
}

// A sheet's openings of one name are one line, as quantities.csv buys them by the tool, drawn
// in each colour their values have: "2 Hole D30" and "3 Hole D30" were two lines.
TEST(Legend, OpeningsOfOneNameAreOneLineInEveryColour) {
  Design d = design(4, 2, {{"3/4", "3/4"}, {"3/4", "3/4"}});
  const CurdField f = curdle(d, 2, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("perforation"));
  spec.module_w = spec.module_h = 40;
  spec.own<PerforationKeys>().thickness = 2;
  spec.own<PerforationKeys>().holes = {{16, -7, 6}, {16, 7, -6}};
  spec.materials = {"Sheet", "Hole D16", "Hole D16", "Hole D16"};
  const Layout layout = make_layout(d, f, d.field, spec);
  ASSERT_NE(layout.legend[1].colour, layout.legend[2].colour);
  EXPECT_EQ(layout.legend[2].same_as, 1u);
  EXPECT_EQ(layout.legend[3].same_as, 1u);
  const std::vector<LegendLine> lines = legend_lines(layout.legend);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].values, "1, 2, 3");
  EXPECT_EQ(lines[0].looks.size(), 3u);
  EXPECT_EQ(lines[0].count,
            layout.legend[1].count + layout.legend[2].count + layout.legend[3].count);
}

}  // namespace curdle

namespace curdle {

// A park's legend lists what is planted and built, one line a material with its count or area
// and the pit drawn dashed; it listed value combinations ("3 tree+bench: 5 cells").
TEST(Legend, AParkListsWhatIsPlantedAndBuilt) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = test::trees_and_benches();
  spec.own<ParkKeys>().elements[0].order = {"Tilia cordata", {18, 20}, 600, {900, 900}};
  const Layout layout = make_layout(d, curdle(d, 4, d.field), d.field, spec);
  const std::vector<MaterialLine> lines = material_lines(layout);
  std::map<std::string, uint64_t> standing;
  double ground = 0, listed = 0;
  for (const Element& e : layout.elements) {
    if (e.stands) ++standing[e.type];
    if (!e.stands) ground += e.area();
  }
  ASSERT_EQ(lines.size(), 4u);  // tree, bench, grey and white paving
  EXPECT_EQ(lines[0].text(), "bench: " + std::to_string(standing["bench"]));
  EXPECT_EQ(lines[1].text(),
            "tree (Tilia cordata), pit 900 x 900 dashed: " + std::to_string(standing["tree"]));
  EXPECT_GT(lines[2].area, lines[3].area);  // surfaces largest first
  for (const MaterialLine& l : lines) {
    EXPECT_EQ(l.text().find('+'), std::string::npos) << l.text();
    if (!l.stands) listed += l.area;
  }
  EXPECT_NEAR(listed, ground, 1e-3);
  EXPECT_NE(lines[2].text().find(" m², "), std::string::npos) << lines[2].text();
}

}  // namespace curdle
