// Tests of dxf_document.h: a DXF in millimetres with its extents, valid layer names and closed
// polylines, read back as text.
#include "export/dxf/dxf_document.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "picture_support.h"

namespace curdle {
namespace {

TEST(DxfDocument, MillimetresExtentsLayersAndClosedPolylines) {
  EXPECT_EQ(dxf_layer_name(hole_layer(22.6)), "HOLE_D22_6");
  // Text is one line (a line break would start a group code of its own); letters in any script
  // stay as they are, UTF-8 as AutoCAD 2007 writes them, beyond the BMP too; a byte that is not
  // UTF-8 does not pass.
  EXPECT_EQ(dxf_text("Grès\n  8\r\nINJECTED"), "Grès   8  INJECTED");
  EXPECT_EQ(dxf_layer_name("Grès Łódź Ψ"), "Grès Łódź Ψ");
  EXPECT_EQ(dxf_text("O'Hare 瓦 – € 🌳"), "O'Hare 瓦 – € 🌳");
  EXPECT_EQ(dxf_text("a\xE8"
                     "b"),
            "a b");
  const std::string layer = dxf_layer_name("Brick <red>/2");
  EXPECT_EQ(layer.find_first_of("<>/\\\":;?*|=`"), std::string::npos) << layer;
  const auto dir = test::scratch("dxf");
  {
    DxfDocument dxf(dir / "a.dxf", {{"BRICK", Rgb{200, 60, 40}, true}, {"ID", Rgb{0, 0, 0}, false}},
                    Rect{0, 0, 1200, 600});
    dxf.rect("BRICK", Rect{0, 0, 215, 65});
    dxf.polygon("BRICK", Ring{{300, 0}, {400, 0}, {350, 80}});
  }
  std::ifstream in(dir / "a.dxf");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  EXPECT_NE(s.find("$INSUNITS\n 70\n4\n"), std::string::npos);
  EXPECT_NE(s.find("$EXTMAX\n 10\n1200"), std::string::npos);
  size_t polylines = 0;
  for (size_t at = s.find("LWPOLYLINE"); at != std::string::npos; at = s.find("LWPOLYLINE", at + 1))
    ++polylines;
  EXPECT_GE(polylines, 2u);
  EXPECT_NE(s.find("\nBRICK\n"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curdle
