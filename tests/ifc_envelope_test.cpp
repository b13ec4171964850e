// Tests of ifc_envelope.h, through layout.ifc of the pavilion: a wall per façade nesting its
// units, each unit a building element part in the storeys through it, an opening per window
// and door voiding its wall and filled, each in the storey its sill stands in, storeys at the
// recipe's floor-to-floor height, and a corner unit one part with one prism.
#include "export/ifc/ifc_envelope.h"

#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>

#include "building_support.h"
#include "export/ifc/ifc.h"

namespace curdle {
namespace {

size_t count(const std::string& text, const std::string& entity) {
  std::string key = "=";  // appended: GCC 12 warns falsely on "=" + string
  key += entity;
  key += '(';
  size_t n = 0;
  for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) ++n;
  return n;
}

// The line of the entity `#id=...`.
std::string line_of(const std::string& text, const std::string& id) {
  std::string key = "\n#";
  key += id;
  key += '=';
  const size_t at = text.find(key);
  return at == std::string::npos ? "" : text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

TEST(IfcEnvelope, WallsNestTheirUnitsAndOpeningsVoidThemFilledByWindowsAndDoors) {
  const Layout l = test::lay_recipe(test::pavilion_recipe(R"(storey = 3525
[layout.building.windows]
size = [1200, 1500]
every = 3000
clear = 900
sill = 900
[[layout.building.openings]]
facade = "S"
rect = [9400, 0, 1200, 2400]
type = "door"
)"));
  std::ostringstream out;
  write_layout_ifc(out, l);
  const std::string ifc = out.str();
  EXPECT_EQ(count(ifc, "IFCWALL"), 6u);
  EXPECT_EQ(count(ifc, "IFCRELNESTS"), 6u);
  size_t common = 0;  // each wall's common set, saying it stands outside
  for (size_t at = ifc.find("'Pset_WallCommon'"); at != std::string::npos;
       at = ifc.find("'Pset_WallCommon'", at + 1))
    ++common;
  EXPECT_EQ(common, 6u);
  EXPECT_EQ(count(ifc, "IFCBUILDINGELEMENTPART"), l.elements.size());
  EXPECT_EQ(count(ifc, "IFCCOVERING"), 0u);
  EXPECT_EQ(count(ifc, "IFCOPENINGELEMENT"), 41u);  // 40 windows by rule and the door
  EXPECT_EQ(count(ifc, "IFCRELVOIDSELEMENT"), 41u);
  EXPECT_EQ(count(ifc, "IFCRELFILLSELEMENT"), 41u);
  EXPECT_EQ(count(ifc, "IFCWINDOW"), 40u);
  EXPECT_EQ(count(ifc, "IFCDOOR"), 1u);
  EXPECT_NE(ifc.find("'Level 1',$,$,#"), std::string::npos);
  EXPECT_NE(ifc.find(",.ELEMENT.,3525.);"), std::string::npos);
  // Each storey contains what stands in it: Level 0 the walls, the door and the ground
  // floor's 20 windows; Level 1 the 20 upper windows (sills at 4425). The parts are in the
  // storeys through their walls, not contained as well.
  std::map<std::string, std::string> storey_of;  // storey id -> its name
  for (size_t at = ifc.find("=IFCBUILDINGSTOREY("); at != std::string::npos;
       at = ifc.find("=IFCBUILDINGSTOREY(", at + 1)) {
    const size_t start = ifc.rfind('#', at) + 1;
    const std::string line = line_of(ifc, ifc.substr(start, at - start));
    storey_of[ifc.substr(start, at - start)] = line.substr(line.find("'Level"), 9);
  }
  std::map<std::string, std::map<std::string, size_t>> held;  // storey -> entity -> count
  std::smatch m;
  for (size_t at = ifc.find("=IFCRELCONTAINEDINSPATIALSTRUCTURE("); at != std::string::npos;
       at = ifc.find("=IFCRELCONTAINEDINSPATIALSTRUCTURE(", at + 1)) {
    const std::string line = ifc.substr(at, ifc.find('\n', at) - at);
    const size_t open = line.find(",$,$,(") + 6, close = line.find(')', open);
    const std::string storey = storey_of[line.substr(close + 3, line.size() - close - 5)];
    std::stringstream ids(line.substr(open, close - open));
    for (std::string id; std::getline(ids, id, ',');) {
      const std::string held_line = line_of(ifc, id.substr(1));
      const size_t eq = held_line.find('=');
      ++held[storey][held_line.substr(eq + 1, held_line.find('(') - eq - 1)];
    }
  }
  EXPECT_EQ(held["'Level 0'"]["IFCWALL"], 6u);
  EXPECT_EQ(held["'Level 0'"]["IFCDOOR"], 1u);
  EXPECT_EQ(held["'Level 0'"]["IFCWINDOW"], 20u);
  EXPECT_EQ(held["'Level 1'"]["IFCWINDOW"], 20u);
  EXPECT_EQ(held["'Level 0'"]["IFCBUILDINGELEMENTPART"], 0u);
  EXPECT_EQ(held["'Level 1'"].size(), 1u);
  // A quoin is one part whose body is one prism, its footprint cut to the corner.
  const Element* quoin = nullptr;
  for (const Element& e : l.elements)
    if (e.corner == 0 && !quoin) quoin = &e;
  ASSERT_NE(quoin, nullptr);
  std::string named = ",'";
  named += quoin->id;
  named += "',$,";
  const size_t at = ifc.find(named);
  ASSERT_NE(at, std::string::npos);
  const std::string part =
      ifc.substr(ifc.rfind('\n', at) + 1, ifc.find('\n', at) - ifc.rfind('\n', at) - 1);
  ASSERT_EQ(part.find("IFCBUILDINGELEMENTPART("), part.find('=') + 1) << part;
  // Its representation (after its placement), a product shape of one body of one solid.
  ASSERT_TRUE(std::regex_search(part, m, std::regex("',#\\d+,#(\\d+),'")));
  const std::string shape = line_of(ifc, m[1].str());
  ASSERT_TRUE(std::regex_search(shape, m, std::regex("\\(\\$,\\$,\\(#(\\d+)\\)\\)")));
  const std::string line = line_of(ifc, m[1].str());
  EXPECT_NE(line.find("'SweptSolid',(#"), std::string::npos);
  EXPECT_EQ(std::count(line.begin(), line.end(), '#'), 3) << line;  // itself, context, 1 solid
  ASSERT_TRUE(std::regex_search(line, m, std::regex("'SweptSolid',\\(#(\\d+)\\)")));
  const std::string solid = line_of(ifc, m[1].str());
  ASSERT_TRUE(std::regex_search(solid, m, std::regex("IFCEXTRUDEDAREASOLID\\(#(\\d+),")));
  EXPECT_NE(line_of(ifc, m[1].str()).find("IFCARBITRARYCLOSEDPROFILEDEF"), std::string::npos);
}

// A one-brick wall's IfcWall has a body, its backing leaf: an extruded solid a backing's depth
// (215 - 102.5 - 10 mm) behind the face leaf; a half-brick leaf's walls have none (their shape
// is their units').
TEST(IfcEnvelope, AOneBrickWallsBodyIsItsBackingLeaf) {
  auto walls = [](const std::string& building) {
    const Layout l = test::lay_recipe(test::pavilion_recipe(building, "bond = \"english\"\n"));
    std::ostringstream out;
    write_layout_ifc(out, l);
    std::vector<std::string> found;
    const std::string text = out.str();
    for (size_t at = text.find("=IFCWALL("); at != std::string::npos;
         at = text.find("=IFCWALL(", at + 1))
      found.push_back(text.substr(at, text.find('\n', at) - at));
    return std::make_pair(found, text);
  };
  const auto [solid, solid_text] = walls("wall = \"one-brick\"\n");
  ASSERT_EQ(solid.size(), 6u);
  for (const std::string& w : solid) EXPECT_EQ(w.find(",$,'"), std::string::npos) << w;
  EXPECT_NE(solid_text.find("IFCEXTRUDEDAREASOLID"), std::string::npos);
  EXPECT_NE(solid_text.find(",102.5)"), std::string::npos) << "a backing leaf 102.5 mm deep";
  const auto [leaf, leaf_text] = walls("");
  ASSERT_EQ(leaf.size(), 6u);
  for (const std::string& w : leaf) EXPECT_NE(w.find(",$,'"), std::string::npos) << w;
}

}  // namespace
}  // namespace curdle
