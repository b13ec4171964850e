// layout.ifc as written: one element per schedule row with its ID as Name and Tag, the right
// IFC class and spatial structure per kind, openings voiding their sheets, names in 7-bit
// STEP, and the same bytes for the same run. web-ifc reads every pattern's model back in
// tests/js/ifc_check.mjs (ctest js.ifc_read_back).
#include "export/ifc/ifc.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "app/outputs.h"
#include "test_support.h"

namespace curdle {
namespace {

struct Written {
  std::string ifc, schedule;
};

Written written(const std::string& pattern, const std::vector<std::string>& overrides = {}) {
  const std::string path = std::string(CURDLE_SOURCE_DIR) + "/patterns/" + pattern;
  const app::Run run = test::run_recipe(path, app::read_recipe_file(path), overrides);
  app::MemorySink sink;
  app::write_outputs(run, app::select_outputs(run, {"layout.ifc", "schedule.csv"}, nullptr), sink,
                     0, nullptr);
  return {sink.files().at("layout.ifc"), sink.files().at("schedule.csv")};
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The model's owner history, "#n": every rooted entity refers to it.
std::string owner_history(const std::string& ifc) {
  const size_t at = ifc.find("=IFCOWNERHISTORY(");
  return at == std::string::npos ? "" : ifc.substr(ifc.rfind('#', at), at - ifc.rfind('#', at));
}

// An element's owner history and name as the courtyard's paving tiles are written.
std::string named_by(const std::string& owner, const std::string& id) {
  std::string text = ",";
  text += owner;
  text += ",'";
  text += id;
  text += "',$,'paving tile',";
  return text;
}

std::vector<std::string> schedule_ids(const std::string& schedule) {
  std::vector<std::string> ids;
  std::istringstream in(schedule);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) ids.push_back(line.substr(0, line.find(',')));
  return ids;
}

TEST(Ifc, EveryScheduleRowIsAnElementNamedAndTaggedByItsId) {
  const Written w = written("courtyard-l-shaped.toml");
  const auto ids = schedule_ids(w.schedule);
  ASSERT_GT(ids.size(), 100u);
  EXPECT_EQ(count(w.ifc, "=IFCCOVERING("), ids.size());
  for (const std::string& id : ids)
    EXPECT_NE(w.ifc.find(named_by(owner_history(w.ifc), id)), std::string::npos) << id;
  // Ground works: in an external space on the site, no building.
  EXPECT_EQ(count(w.ifc, "=IFCSITE("), 1u);
  EXPECT_EQ(count(w.ifc, "=IFCBUILDING("), 0u);
  EXPECT_EQ(count(w.ifc, "'External works',$,$,"), 1u);
  EXPECT_NE(w.ifc.find(".ELEMENT.,.EXTERNAL.,0.);"), std::string::npos);
  EXPECT_NE(w.ifc.find(".FLOORING.);"), std::string::npos);
  // Types per material and stock size, with the tile's size in curdle's own set: IFC4 has none,
  // and a Pset_ name is buildingSMART's to give.
  EXPECT_EQ(count(w.ifc, "=IFCCOVERINGTYPE("), 2u);
  EXPECT_NE(w.ifc.find("'TileLength',$,IFCPOSITIVELENGTHMEASURE(600.)"), std::string::npos);
  EXPECT_EQ(count(w.ifc, "'Curdle_Tiling'"), 2u);
  const std::set<std::string> ifc4_sets{"Pset_CoveringCommon", "Pset_PlateCommon",
                                        "Pset_WallCommon", "Pset_OpeningElementCommon",
                                        "Pset_BuildingElementProxyCommon"};
  for (size_t at = w.ifc.find("'Pset_"); at != std::string::npos; at = w.ifc.find("'Pset_", at + 1))
    EXPECT_TRUE(ifc4_sets.contains(w.ifc.substr(at + 1, w.ifc.find('\'', at + 1) - at - 1)))
        << w.ifc.substr(at, 40);
  EXPECT_NE(w.ifc.find("IFCMATERIAL('Basalt slab 600 x 300',$,$)"), std::string::npos);
}

// [layout.georef]: the model placed on the projected CRS as a BIM coordinator places one, its
// origin at the easting and northing, its x axis turned, millimetres to the map's metres; none
// without it.
TEST(Ifc, AGeoreferencedLayoutCarriesItsMapConversion) {
  const Written w = written("courtyard-l-shaped.toml",
                            {"layout.georef={epsg=27700, easting=530000.5, northing=180000.25, "
                             "rotation=30}"});
  EXPECT_EQ(count(w.ifc, "=IFCPROJECTEDCRS('EPSG:27700',$,$,$,$,$,#"), 1u);
  EXPECT_NE(w.ifc.find(",530000.5,180000.25,0.,0.8660254037844387,0.49999999999999994,0.001);"),
            std::string::npos);
  EXPECT_EQ(count(written("courtyard-l-shaped.toml").ifc, "IFCMAPCONVERSION"), 0u);
}

TEST(Ifc, KindsBecomeTheClassesABimModellerWouldChoose) {
  const Written facade = written("brick-facade-five-storeys.toml");
  EXPECT_EQ(count(facade.ifc, "=IFCBUILDINGSTOREY("), 1u);
  EXPECT_EQ(count(facade.ifc, "=IFCCOVERING("), schedule_ids(facade.schedule).size());
  EXPECT_EQ(count(facade.ifc, ".FLOORING."), 0u);  // cladding, every one
  const Written park = written("paper/fig5a-park.toml");
  const auto ids = schedule_ids(park.schedule);
  size_t trees = 0, benches = 0;
  for (const std::string& id : ids)
    trees += id.ends_with("-tree"), benches += id.ends_with("-bench");
  ASSERT_GT(trees, 0u);
  EXPECT_EQ(count(park.ifc, "=IFCGEOGRAPHICELEMENT("), trees);
  EXPECT_EQ(count(park.ifc, "=IFCFURNITURE("), benches);
  EXPECT_EQ(count(park.ifc, "=IFCCOVERING("), ids.size() - trees - benches);
  // A tree's and a bench's quantities say how tall they stand (a trunk of 2.2 m and a canopy as
  // tall as wide; 450 mm), not the paving's 30 mm thickness.
  std::set<double> heights;
  const std::string height = "IFCQUANTITYLENGTH('Height',$,$,";
  for (size_t at = park.ifc.find(height); at != std::string::npos;
       at = park.ifc.find(height, at + 1))
    heights.insert(std::stod(park.ifc.substr(at + height.size(), 20)));
  ASSERT_FALSE(heights.empty());
  EXPECT_TRUE(heights.contains(450.0));
  for (const double h : heights) EXPECT_TRUE(h == 450.0 || h > 2200.0) << h;
  const Written blocks = written("stacked-blocks.toml");
  EXPECT_EQ(count(blocks.ifc, "=IFCBUILDINGELEMENTPROXY("), schedule_ids(blocks.schedule).size());
}

// The holes are in the sheet's body (a profile with voids: one solid, no Boolean operation for
// a reader to run), and each opening is an annotation of its sheet, drawn by its outline and
// assigned to it: no IfcOpeningElement voids a sheet that has the hole already (web-ifc runs a
// Boolean operation for each, and gives up on a sheet with more than 150).
TEST(Ifc, OpeningsAreHolesInTheirSheetsProfileAndAnnotateIt) {
  const Written w = written("paper/fig4-perforation.toml");
  const size_t openings = schedule_ids(w.schedule).size();
  EXPECT_EQ(count(w.ifc, "=IFCANNOTATION("), openings);
  EXPECT_EQ(count(w.ifc, "=IFCOPENINGELEMENT("), 0u);
  EXPECT_EQ(count(w.ifc, "=IFCRELVOIDSELEMENT("), 0u);
  EXPECT_EQ(count(w.ifc, "=IFCPLATE("), 1u);
  EXPECT_EQ(count(w.ifc, "=IFCEXTRUDEDAREASOLID("), 1u);  // the sheet's, and no opening's
  EXPECT_EQ(count(w.ifc, "'Annotation','Curve2D'"), openings);
  const std::regex assigned(
      "IFCRELASSIGNSTOPRODUCT\\('[^']*',#\\d+,'holes',\\$,\\(([^)]*)\\),\\$,#(\\d+)\\)");
  std::smatch a;
  ASSERT_TRUE(std::regex_search(w.ifc, a, assigned));
  EXPECT_EQ(count(a[1].str(), "#"), openings);
  EXPECT_NE(w.ifc.find("#" + a[2].str() + "=IFCPLATE("), std::string::npos);
  const std::regex voids("IFCARBITRARYPROFILEDEFWITHVOIDS\\(\\.AREA\\.,\\$,#\\d+,\\(([^)]*)\\)\\)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(w.ifc, m, voids));
  EXPECT_EQ(count(m[1].str(), "#"), openings);
  EXPECT_NE(w.ifc.find("'Qto_PlateBaseQuantities'"), std::string::npos);
}

// What Revit, ArchiCAD and Solibri look for: one owner history on every rooted entity, IFC4's
// standard sets beside curdle's own, each element placed at its own corner, and one solid per
// element, an L-shaped cut piece included.
TEST(Ifc, ElementsCarryOwnerHistoryStandardSetsTheirOwnPlacementAndOneSolid) {
  const Written w = written("brick-facade-five-storeys.toml");
  const size_t elements = schedule_ids(w.schedule).size();
  EXPECT_EQ(count(w.ifc, "=IFCOWNERHISTORY("), 1u);
  const std::regex rooted("=IFC[A-Z]+\\('[0-9A-Za-z_$]{22}',([^,]*),");
  size_t roots = 0;
  for (auto it = std::sregex_iterator(w.ifc.begin(), w.ifc.end(), rooted);
       it != std::sregex_iterator(); ++it, ++roots)
    ASSERT_EQ((*it)[1].str(), owner_history(w.ifc)) << (*it)[0].str();
  EXPECT_GT(roots, 4 * elements);
  EXPECT_EQ(count(w.ifc, "'Pset_CoveringCommon'"), elements);
  EXPECT_EQ(count(w.ifc, "'Qto_CoveringBaseQuantities'"), elements);
  EXPECT_EQ(count(w.ifc, "'Curdle_Quantities'"), elements);
  EXPECT_EQ(count(w.ifc, "'BaseQuantities'"), 0u);
  // A property is written once and held by every set that has it: each covering's common set
  // says it is external through the one IsExternal = true.
  const std::string external = "=IFCPROPERTYSINGLEVALUE('IsExternal',$,IFCBOOLEAN(.T.),$)";
  ASSERT_EQ(count(w.ifc, external), 1u);
  const size_t at = w.ifc.find(external);
  const std::string id = w.ifc.substr(w.ifc.rfind('#', at), at - w.ifc.rfind('#', at));
  const std::regex holds("'Pset_CoveringCommon',\\$,\\([^)]*" + id + "[,)]");
  EXPECT_EQ(static_cast<size_t>(std::distance(
                std::sregex_iterator(w.ifc.begin(), w.ifc.end(), holds), std::sregex_iterator())),
            elements);
  // One solid per element, whatever its shape: the façade has pieces cut round its windows.
  ASSERT_NE(w.schedule.find("F-R07-C18,"), std::string::npos);  // cut round a window: L-shaped
  EXPECT_EQ(count(w.ifc, "=IFCEXTRUDEDAREASOLID("), elements);
  // Each element at its own corner: as many element placements as elements, none at the origin.
  const std::regex element_placement(
      "=IFCCOVERING\\('[^']{22}',#\\d+,'[^']*',\\$,'[^']*',(#\\d+),");
  std::set<std::string> placements;
  for (auto it = std::sregex_iterator(w.ifc.begin(), w.ifc.end(), element_placement);
       it != std::sregex_iterator(); ++it)
    placements.insert((*it)[1].str());
  EXPECT_EQ(placements.size(), elements);
}

TEST(Ifc, TheSameRunGivesTheSameBytesAndAnotherSeedOtherIds) {
  const Written a = written("courtyard-l-shaped.toml"), b = written("courtyard-l-shaped.toml");
  EXPECT_EQ(a.ifc, b.ifc);
  const Written c = written("courtyard-l-shaped.toml", {"seed=9"});
  const std::regex guid("IFCPROJECT\\('([^']{22})'");
  std::smatch ma, mc;
  ASSERT_TRUE(std::regex_search(a.ifc, ma, guid));
  ASSERT_TRUE(std::regex_search(c.ifc, mc, guid));
  EXPECT_NE(ma[1].str(), mc[1].str());
  EXPECT_NE(a.ifc.find("IFCLABEL('8')"), std::string::npos);  // the seed, to reproduce it
}

TEST(Ifc, NamesInAnyScriptAreWrittenAsSevenBitStep) {
  const Written w =
      written("courtyard-l-shaped.toml", {"layout.materials=[\"Grès cérame\", \"O'Hare 瓦\"]"});
  for (const char c : w.ifc) ASSERT_LT(static_cast<unsigned char>(c), 0x80u);
  EXPECT_NE(w.ifc.find("IFCMATERIAL('Gr\\X2\\00E8\\X0\\s c\\X2\\00E9\\X0\\rame',$,$)"),
            std::string::npos);
  EXPECT_NE(w.ifc.find("IFCMATERIAL('O''Hare \\X2\\74E6\\X0\\',$,$)"), std::string::npos);
}

}  // namespace
}  // namespace curdle
