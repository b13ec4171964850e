#include "site/site.h"

#include <gtest/gtest.h>

#include <cmath>

#include "dxf_text.h"
#include "layout/zone.h"
#include "site/dxf_reader.h"

namespace curdle::site {
namespace {

using testing::DxfText;

LayerMap courtyard_map(bool with_pit = false) {
  LayerMap map;
  map.file = "court.dxf";
  map.outline = "A-OTLN";
  if (with_pit) map.zones = {{"TREE_PIT", ZoneRule::exclude, 0}};
  return map;
}

Site site_of(const DxfText& dxf, const LayerMap& map) {
  return site_from(read_dxf(dxf.text(), map.file, {}), map);
}

std::string refusal(const DxfText& dxf, const LayerMap& map) {
  try {
    site_of(dxf, map);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(read)";
}

TEST(SiteTest, ChainsLinesAndArcsIntoOneOutline) {
  DxfText dxf(6);  // metres
  // A 10 x 6 m floor whose top is an arc through (5, 7): lines and an ARC, in no order, one
  // end 0.3 mm off (joined: under 0.5 mm).
  dxf.begin_entities_only()
      .line("A-OTLN", "1", 10, 6, 10, 0)
      .line("A-OTLN", "2", 0, 0.0003, 0, 6)
      .line("A-OTLN", "3", 0, 0, 10, 0)
      .arc("A-OTLN", "4", 5, -6, 13, std::atan2(12, 5) * 180 / 3.14159265358979323846,
           180 - std::atan2(12, 5) * 180 / 3.14159265358979323846)
      .circle("TREE_PIT", "5", 3, 2, 0.7)
      .circle("NOTES", "6", 3, 2, 0.2);
  const Site s = site_of(dxf, courtyard_map(true));
  EXPECT_EQ(arc_count(s.outline), 1u);
  const Rect b = contour_bounds(s.outline);
  EXPECT_NEAR(b.w, 10000, 1e-6);
  EXPECT_NEAR(b.top(), 7000, 1e-6);  // the arc's crown
  ASSERT_EQ(s.zones.size(), 1u);
  EXPECT_NEAR(contour_area(s.zones[0].contour), 3.14159265358979323846 * 700 * 700, 1e-3);
  EXPECT_NE(s.summary.find("outline 10,000 x 7,000 mm with 1 arc; 1 zone (TREE_PIT exclude) "
                           "from court.dxf, units m"),
            std::string::npos)
      << s.summary;
  bool ignored = false;
  for (const auto& n : s.notes) ignored = ignored || n.find("ignored: NOTES") != std::string::npos;
  EXPECT_TRUE(ignored);
}

TEST(SiteTest, AnOpenOutlineNamesItsGap) {
  DxfText dxf;
  dxf.begin_entities_only()
      .line("A-OTLN", "A1", 0, 0, 1000, 0)
      .line("A-OTLN", "A2", 1000, 0, 1000, 800)
      .line("A-OTLN", "A3", 1000, 800, 0, 800)
      .line("A-OTLN", "A4", 0, 800, 0, 2);  // 2 mm short
  const std::string m = refusal(dxf, courtyard_map());
  EXPECT_NE(m.find("is not closed"), std::string::npos) << m;
  EXPECT_NE(m.find("(0, 2)"), std::string::npos) << m;
  EXPECT_NE(m.find("(0, 0)"), std::string::npos) << m;
  EXPECT_NE(m.find("LINE A1"), std::string::npos) << m;
}

TEST(SiteTest, ACrossingOutlineNamesTheCrossing) {
  DxfText dxf;
  dxf.begin_entities_only().lwpolyline(
      "A-OTLN", "B0", {{0, 0, 0}, {1000, 1000, 0}, {1000, 0, 0}, {0, 1000, 0}}, true);
  const std::string m = refusal(dxf, courtyard_map());
  EXPECT_NE(m.find("crosses itself at (500, 500)"), std::string::npos) << m;
}

TEST(SiteTest, NamedLayersMustHoldShapes) {
  DxfText dxf;
  dxf.begin_entities_only().lwpolyline("A-OTLN", "1", {{0, 0, 0}, {1000, 0, 0}, {1000, 1000, 0}},
                                       true);
  const std::string m = refusal(dxf, courtyard_map(true));
  EXPECT_NE(m.find("layer \"TREE_PIT\" (a zone) has nothing on it; the layers with shapes are "
                   "\"A-OTLN\""),
            std::string::npos)
      << m;
}

TEST(SiteTest, UnitsMustBeSaidAndPlausible) {
  DxfText unitless(0);
  unitless.begin_entities_only().lwpolyline("A-OTLN", "1", {{0, 0, 0}, {14, 0, 0}, {14, 9, 0}},
                                            true);
  LayerMap map = courtyard_map();
  EXPECT_NE(refusal(unitless, map).find("does not say its units"), std::string::npos);
  map.unit_mm = 1000, map.unit_name = "m";
  EXPECT_NEAR(contour_bounds(site_of(unitless, map).outline).w, 14000, 1e-9);
  // 14,000 units of metres: a 14 km courtyard is a drawing in millimetres.
  DxfText metres(6);
  metres.begin_entities_only().lwpolyline("A-OTLN", "1",
                                          {{0, 0, 0}, {14000, 0, 0}, {14000, 9000, 0}}, true);
  map = courtyard_map();
  const std::string m = refusal(metres, map);
  EXPECT_NE(m.find("too large"), std::string::npos) << m;
  EXPECT_NE(m.find("units = \"mm\""), std::string::npos) << m;
  // 14 x 9 units of millimetres is a drawing in metres.
  DxfText tiny(4);
  tiny.begin_entities_only().lwpolyline("A-OTLN", "1", {{0, 0, 0}, {14, 0, 0}, {14, 9, 0}}, true);
  EXPECT_NE(refusal(tiny, map).find("units = \"m\""), std::string::npos);
}

TEST(SiteTest, FarOriginsKeepTheirPrecisionAndAreReported) {
  DxfText utm(6);
  const double x0 = 5123456.789, y0 = 2345678.123;  // metres, a national grid
  utm.begin_entities_only().lwpolyline(
      "A-OTLN", "1", {{x0, y0, 0}, {x0 + 14.001, y0, 0}, {x0 + 14.001, y0 + 9, 0}, {x0, y0 + 9, 0}},
      true);
  const Site s = site_of(utm, courtyard_map());
  EXPECT_NEAR(s.outline[1].x, 14001, 1e-6);  // a millimetre kept 5,000 km out
  EXPECT_EQ(s.outline[0].x, 0);
  bool said = false;
  for (const auto& n : s.notes) said = said || n.find("5,123,456,789") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(SiteTest, WindowBlocksGiveTheirOuterLineAsTheOpening) {
  DxfText dxf;
  dxf.begin_blocks()
      .block("WIN")
      .lwpolyline("0", "10", {{0, 0, 0}, {1200, 0, 0}, {1200, 1500, 0}, {0, 1500, 0}}, true)
      .lwpolyline("0", "11", {{50, 50, 0}, {1150, 50, 0}, {1150, 1450, 0}, {50, 1450, 0}}, true)
      .line("0", "12", 600, 50, 600, 1450)
      .end_block()
      .begin_entities()
      .lwpolyline("A-WALL", "1", {{0, 0, 0}, {6000, 0, 0}, {6000, 3000, 0}, {0, 3000, 0}}, true)
      .insert("A-GLAZ", "20", "WIN", 1000, 900)
      .insert("A-GLAZ", "21", "WIN", 4000, 900);
  LayerMap map;
  map.file = "elev.dxf";
  map.outline = "A-WALL";
  map.openings = {"A-GLAZ"};
  const Site s = site_of(dxf, map);
  ASSERT_EQ(s.openings.size(), 2u);
  EXPECT_NEAR(contour_area(s.openings[0]), 1200 * 1500, 1e-6);
  EXPECT_NEAR(contour_bounds(s.openings[1]).x, 4000, 1e-9);
}

TEST(SiteTest, AnOpeningOutsideTheOutlineIsRefused) {
  DxfText dxf;
  dxf.begin_entities_only()
      .lwpolyline("A-WALL", "1", {{0, 0, 0}, {6000, 0, 0}, {6000, 3000, 0}, {0, 3000, 0}}, true)
      .lwpolyline("A-GLAZ", "7C", {{7000, 0, 0}, {8000, 0, 0}, {8000, 1000, 0}, {7000, 1000, 0}},
                  true);
  LayerMap map;
  map.file = "elev.dxf";
  map.outline = "A-WALL";
  map.openings = {"A-GLAZ"};
  const std::string m = refusal(dxf, map);
  EXPECT_NE(m.find("LWPOLYLINE 7C on layer \"A-GLAZ\" lies outside the outline"), std::string::npos)
      << m;
}

TEST(SiteTest, UnitNames) {
  EXPECT_EQ(unit_mm("in"), 25.4);
  EXPECT_EQ(unit_mm("m"), 1000);
  EXPECT_EQ(unit_mm("furlong"), 0);
}

}  // namespace
}  // namespace curdle::site

namespace curdle::site {
namespace {

TEST(SiteTest, TheOriginMovesTheDatum) {
  testing::DxfText dxf;
  dxf.begin_entities_only().lwpolyline("A-OTLN", "1",
                                       {{2000, 1000, 0}, {5000, 1000, 0}, {5000, 3000, 0}}, true);
  LayerMap map;
  map.file = "court.dxf";
  map.outline = "A-OTLN";
  // The drawing's own origin: the outline stands 2 m in and 1 m up.
  EXPECT_NEAR(contour_bounds(site_from(read_dxf(dxf.text(), map.file, {}), map).outline).x, 2000,
              1e-9);
  map.origin_at_outline = true;
  Site s = site_from(read_dxf(dxf.text(), map.file, {}), map);
  EXPECT_EQ(contour_bounds(s.outline).x, 0);
  EXPECT_EQ(s.datum[0], 2000);
  map.origin_at_outline = false;
  map.origin = std::array<double, 2>{1000, 500};
  s = site_from(read_dxf(dxf.text(), map.file, {}), map);
  EXPECT_EQ(s.outline[0].x, 1000);
  EXPECT_EQ(s.outline[0].y, 500);
  // A datum right of the outline's corner would put it at negative x: refused.
  map.origin = std::array<double, 2>{3000, 0};
  EXPECT_THROW(site_from(read_dxf(dxf.text(), map.file, {}), map), InputError);
}

TEST(SiteTest, ShapesInsideAZoneAreNotZonesOfTheirOwn) {
  // A pit block: its circle, the trunk inside, a grille of lines; inserted twice.
  DxfText dxf(6);
  dxf.begin_blocks()
      .block("PIT")
      .circle("0", "20", 0, 0, 0.75)
      .circle("0", "21", 0, 0, 0.2)
      .line("0", "22", -0.5, -0.3, 0.5, -0.3)
      .line("0", "23", -0.5, 0.3, 0.5, 0.3)
      .end_block()
      .begin_entities()
      .lwpolyline("A-OTLN", "1", {{0, 0, 0}, {10, 0, 0}, {10, 6, 0}, {0, 6, 0}}, true)
      .insert("TREE_PIT", "30", "PIT", 3, 3)
      .insert("TREE_PIT", "31", "PIT", 7, 3, 1.2, 1.2)
      .circle("TREE_PIT", "32", 3, 3, 0.75);  // drawn again over the first pit
  const Site s = site_of(dxf, courtyard_map(true));
  ASSERT_EQ(s.zones.size(), 2u);
  EXPECT_NEAR(contour_area(s.zones[1].contour), 3.14159265358979323846 * 900 * 900, 1e-3);
  std::string notes;
  for (const std::string& n : s.notes) notes += n + "\n";
  EXPECT_NE(notes.find("2 closed shapes inside others passed over"), std::string::npos) << notes;
  EXPECT_NE(notes.find("4 lines and arcs inside its shapes passed over"), std::string::npos)
      << notes;
  EXPECT_NE(notes.find("1 shapes drawn again over another"), std::string::npos) << notes;
}

TEST(SiteTest, TheOutlineIsPickedWhereALayerHoldsSeveral) {
  DxfText dxf(6);
  dxf.begin_entities_only()
      .lwpolyline("A-OTLN", "1", {{0, 0, 0}, {10, 0, 0}, {10, 6, 0}, {0, 6, 0}}, true)
      .lwpolyline("A-OTLN", "2", {{20, 0, 0}, {40, 0, 0}, {40, 6, 0}, {20, 6, 0}}, true);
  LayerMap map = courtyard_map();
  const std::string m = refusal(dxf, map);
  EXPECT_NE(m.find("holds 2 closed shapes side by side (LWPOLYLINE 1 (10 x 6 at (0, 0)); "
                   "LWPOLYLINE 2 (20 x 6 at (20, 0))); say which is the outline"),
            std::string::npos)
      << m;
  map.pick.around = std::array<double, 2>{5, 3};
  EXPECT_NEAR(contour_bounds(site_of(dxf, map).outline).w, 10000, 1e-6);
  map.pick = {};
  map.pick.handle = "2";
  map.origin_at_outline = true;
  EXPECT_NEAR(contour_bounds(site_of(dxf, map).outline).w, 20000, 1e-6);
  map.pick = {};
  map.pick.largest = true;
  EXPECT_NEAR(contour_bounds(site_of(dxf, map).outline).w, 20000, 1e-6);
  map.pick = {};
  map.pick.around = std::array<double, 2>{15, 3};
  EXPECT_NE(refusal(dxf, map).find("no closed shape on layer \"A-OTLN\" lies around the point "
                                   "(15, 3)"),
            std::string::npos);
}

TEST(SiteTest, AnOpenPieceInABlockIsNamedWithItsBlockAndInsert) {
  DxfText dxf(6);
  dxf.begin_blocks()
      .block("PIT")
      .line("0", "9D", 0, 0, 1.5, 0)
      .end_block()
      .begin_entities()
      .lwpolyline("A-OTLN", "1", {{0, 0, 0}, {10, 0, 0}, {10, 6, 0}, {0, 6, 0}}, true)
      .insert("TREE_PIT", "2F", "PIT", 530012.3456, 3);
  const std::string m = refusal(dxf, courtyard_map(true));
  EXPECT_NE(m.find("LINE 9D in block \"PIT\" (INSERT 2F) ends at (530012.3456, 3) and "
                   "(530013.8456, 3)"),
            std::string::npos)
      << m;
}

// Every contour a drawing gives passes a recipe polygon's checks before anything is cut along
// it: a sliver (its corners meet once in mm), a line, a bow tie are refused by name, where CGAL
// would have been handed them (a sliver crashed its sweep).
TEST(SiteTest, DegenerateZonesAndOpeningsAreRefused) {
  struct Case {
    std::vector<std::array<double, 3>> zone;
    const char* says;
  };
  const Case cases[] = {
      {{{1000, 1000, 0}, {5000, 1000, 0}, {5000, 1000.0000001, 0}, {1000, 1000.0000001, 0}},
       "encloses 0 mm², less than the 1 mm² a zone needs"},
      {{{1000, 1000, 0}, {3000, 1000, 0}, {5000, 1000, 0}}, "encloses 0 mm²"},
      {{{1000, 1000, 0}, {5000, 3000, 0}, {5000, 1000, 0}, {1000, 4000, 0}},
       "crosses or touches itself at ("},
  };
  for (const Case& c : cases) {
    DxfText dxf;
    dxf.begin_entities_only()
        .lwpolyline("A-OTLN", "1", {{0, 0, 0}, {10000, 0, 0}, {10000, 8000, 0}, {0, 8000, 0}}, true)
        .lwpolyline("TREE_PIT", "2", c.zone, true);
    const std::string m = refusal(dxf, courtyard_map(true));
    EXPECT_NE(m.find("the zone LWPOLYLINE 2 on layer \"TREE_PIT\""), std::string::npos) << m;
    EXPECT_NE(m.find(c.says), std::string::npos) << m;
  }
}

// A zone picked as an outline is: the shape of its layer around a point.
TEST(SiteTest, AZoneIsPickedByAPointInsideIt) {
  DxfText dxf(6);
  dxf.begin_entities_only()
      .lwpolyline("A-OTLN", "1", {{0, 0, 0}, {10, 0, 0}, {10, 6, 0}, {0, 6, 0}}, true)
      .circle("TREE_PIT", "2", 3, 3, 0.75)
      .circle("TREE_PIT", "3", 7, 3, 0.9);
  LayerMap map = courtyard_map(true);
  map.zones[0].around = std::array<double, 2>{7.2, 3.1};
  const Site s = site_of(dxf, map);
  ASSERT_EQ(s.zones.size(), 1u);
  EXPECT_NEAR(contour_area(s.zones[0].contour), 3.14159265358979323846 * 900 * 900, 1e-3);
  map.zones[0].around = std::array<double, 2>{5, 5};
  EXPECT_NE(
      refusal(dxf, map).find("no closed shape on layer \"TREE_PIT\" lies around the point (5, 5)"),
      std::string::npos);
}

}  // namespace
}  // namespace curdle::site
