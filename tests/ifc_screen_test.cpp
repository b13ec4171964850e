// Tests of ifc_screen.h: a screen's sheet in IFC is its triangles and a mapped copy of one
// shape per opening, each shape written once.
#include "export/ifc/ifc_screen.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "building_support.h"
#include "export/ifc/step_file.h"
#include "test_support.h"

namespace curdle {
namespace {

using test::occurrences;

TEST(IfcScreen, ASheetsBodyIsItsTrianglesAndAMappedTileAnOpening) {
  std::ifstream in(std::string(CURDLE_SOURCE_DIR) + "/patterns/perforated-screen-curved.toml");
  std::stringstream text;
  text << in.rdbuf();
  const Layout l = test::lay_recipe(text.str());
  const FramedScreen screen = framed_screen(l);
  std::ostringstream out;
  StepWriter w(out, "t.ifc", "IFC4", "ReferenceView_V1.2");
  IfcGeometryWriter g(w, l.chord_tolerance);
  IfcScreenSheets sheets(g, l);
  EXPECT_GT(sheets.body(0, Rgb{180, 180, 180}), 0);
  EXPECT_GT(sheets.body(1, Rgb{180, 180, 180}), 0);
  w.finish();
  const std::string step = out.str();
  const size_t maps = occurrences(step, "IFCREPRESENTATIONMAP(");
  EXPECT_EQ(occurrences(step, "IFCTRIANGULATEDFACESET("), maps)
      << "each sheet, and each shape of tile once";
  EXPECT_EQ(occurrences(step, "IFCMAPPEDITEM("),
            2 + screen.tiled[0].size() + screen.tiled[1].size())
      << "each sheet and a copy an opening";
  EXPECT_GT(screen.tiled[0].size(), 100u);
  EXPECT_LT(maps, 2 + 50u) << "the openings come in a few shapes, each written once";
}

}  // namespace
}  // namespace curdle
