// Tests of layout_dxf.h: every piece a closed polyline on its material's layer, and its ID as
// text on layer ID, for a paving read back as DXF text.
#include "export/layout_dxf.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "layout_support.h"
#include "picture_support.h"

namespace curdle {
namespace {

size_t occurrences(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

TEST(LayoutDxf, EveryPieceOnItsMaterialsLayerWithItsId) {
  const Design d = test::design(2, 2, {{"3/4", "2/3"}});
  LayoutSpec spec = test::layout_spec("paving");
  spec.size = std::array<double, 2>{1500, 1000};  // a row and a column cut
  spec.materials = {"Limestone", "Basalt"};
  const Layout layout = lay_floor(d, spec, 8);
  const auto dir = test::scratch("layout-dxf");
  write_layout_dxf(dir / "layout.dxf", layout);
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

}  // namespace
}  // namespace curdle
