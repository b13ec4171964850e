// Tests of layout_dxf.h: every piece a closed polyline on its material's layer, and its ID as
// text on layer ID, for a paving read back as DXF text.
#include "export/dxf/layout_dxf.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "kinds/park.h"
#include "layout_support.h"
#include "picture_support.h"

namespace curdle {
namespace {

using test::occurrences;

TEST(LayoutDxf, EveryPieceOnItsMaterialsLayerWithItsId) {
  const Design d = test::design(2, 2, {{"3/4", "2/3"}});
  LayoutSpec spec = test::layout_spec("paving");
  spec.size = std::array<double, 2>{1500, 1000};  // a row and a column cut
  spec.materials = {"Limestone", "Basalt"};
  const Layout layout = lay_floor(d, spec, 8);
  const auto dir = test::scratch("layout-dxf");
  write_layout_dxf(dir / "layout.dxf", layout, false);
  std::ifstream in(dir / "layout.dxf");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  size_t basalt = 0;
  for (const Element& e : layout.elements) {
    EXPECT_EQ(occurrences(s, "\n" + e.id + "\n"), 1u) << e.id;
    basalt += e.value == 1;
  }
  // Each piece's polyline and its layer, the outline's on OUTLINE.
  EXPECT_EQ(occurrences(s, "LWPOLYLINE"), layout.elements.size() + 1);
  EXPECT_GE(occurrences(s, "\nBasalt\n"), basalt);
  EXPECT_NE(s.find("\nOUTLINE\n"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// A park's tree pits are rectangles on their own layer, one per tree with a pit, so that the
// groundworks contractor sets them out from the DXF as from the sheets.
TEST(LayoutDxf, TreePitsOnTheirOwnLayer) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = test::trees_and_benches();
  spec.own<ParkKeys>().elements[0].order = {"Tilia cordata", {}, 600, {1200, 1200}};
  spec.size = std::array<double, 2>{24000, 18000};
  const Layout layout = lay_floor(d, spec, 4);
  size_t trees = 0;
  for (const Element& e : layout.elements) trees += e.circle.has_value();
  ASSERT_GT(trees, 0u);
  const auto dir = test::scratch("layout-dxf-pits");
  write_layout_dxf(dir / "layout.dxf", layout, false);
  std::ifstream in(dir / "layout.dxf");
  std::stringstream text;
  text << in.rdbuf();
  // The layer's table entry, then one LWPOLYLINE per pit: "8\nTREE_PITS" per entity.
  EXPECT_EQ(occurrences(text.str(), "\n  8\nTREE_PITS\n"), trees);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curdle
