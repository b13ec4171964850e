// Tests of layout_reader.h.
#include "recipe/layout_reader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <numbers>

#include "kinds/facade.h"
#include "layout/contour.h"
#include "recipe_support.h"

namespace curdle {
TEST(Recipe, BondAndCentredOrigin) {
  const std::string wall =
      with_layout("kind = \"facade\"\npanel = [215, 65]\njoint = 10\nwall = [4000, 2000]\n");
  Recipe r = parse_recipe(wall + "bond = \"half\"\norigin = \"centre\"\n", "r.toml");
  EXPECT_DOUBLE_EQ(r.layout->bond, 0.5);
  EXPECT_TRUE(r.layout->centred);
  EXPECT_NEAR(r.layout->shift[0], centring_shift(4000, 215, 10), 1e-9);
  EXPECT_GT(r.layout->shift[0], 0);
  EXPECT_DOUBLE_EQ(parse_recipe(wall + "bond = \"third\"\n", "r.toml").layout->bond, 1.0 / 3);
  EXPECT_DOUBLE_EQ(parse_recipe(wall + "bond = \"quarter\"\n", "r.toml").layout->bond, 0.25);
  std::string e = error_of(wall + "bond = \"flemish\"\n");
  EXPECT_NE(e.find("layout.bond"), std::string::npos) << e;
  EXPECT_NE(e.find("\"stack\""), std::string::npos) << e;
  e = error_of(wall + "origin = \"centre\"\nshift = [10, 10]\n");
  EXPECT_NE(e.find("layout.shift"), std::string::npos) << e;
  e = error_of(wall + "bond = \"half\"\ncombine = \"keep\"\n");
  EXPECT_NE(e.find("mix"), std::string::npos) << e;
  e = error_of(wall + "origin = \"middle\"\n");
  EXPECT_NE(e.find("\"centre\""), std::string::npos) << e;
}

// layout.pattern: a paver's pattern with the tile's proportions it needs, and nothing that moves
// or shifts a grid beside it.
TEST(Recipe, LayingPattern) {
  const std::string floor = with_layout("kind = \"paving\"\nfloor = [4000, 3000]\njoint = 3\n");
  Recipe r = parse_recipe(floor + "tile = [200, 98.5]\npattern = \"herringbone-45\"\n", "r.toml");
  EXPECT_EQ(r.layout->pattern, LayingPattern::herringbone_45);
  EXPECT_EQ(parse_recipe(floor + "tile = [300, 300]\npattern = \"hexagon-flat\"\n", "r.toml")
                .layout->pattern,
            LayingPattern::hexagon_flat);
  EXPECT_EQ(parse_recipe(floor + "tile = [306, 100]\npattern = \"basketweave\"\n", "r.toml")
                .layout->pattern,
            LayingPattern::basketweave);
  auto fails = [&](const std::string& keys, const std::string& key, const std::string& words) {
    const std::string e = error_of(floor + keys);
    EXPECT_NE(e.find(key), std::string::npos) << e;
    EXPECT_NE(e.find(words), std::string::npos) << e;
  };
  fails("tile = [200, 100]\npattern = \"chevron\"\n", "layout.pattern", "\"herringbone-45\"");
  fails("tile = [200, 100]\npattern = \"herringbone\"\n", "layout.pattern", "203 x 100 mm");
  fails("tile = [250, 100]\npattern = \"basketweave\"\n", "layout.pattern", "n from 2 to 4");
  fails("tile = [300, 260]\npattern = \"hexagon\"\n", "layout.pattern", "[300, 300]");
  fails("tile = [203, 100]\npattern = \"herringbone\"\nbond = \"half\"\n", "layout.bond",
        "pattern");
  fails("tile = [203, 100]\npattern = \"herringbone\"\nshift = [10, 0]\n", "layout.shift",
        "pattern");
  fails("tile = [203, 100]\npattern = \"herringbone\"\norigin = \"centre\"\n", "layout.origin",
        "corner");
  EXPECT_NE(error_of(with_layout("kind = \"paving\"\ntile = [300, 300]\npattern = \"hexagon\"\n"))
                .find("layout.floor"),
            std::string::npos);
}

// The installer's sheets: scale, paper and set named in the recipe, each checked.
TEST(Recipe, InstallerSheetKeys) {
  const std::string wall =
      with_layout("kind = \"facade\"\npanel = [215, 65]\njoint = 10\nwall = [4000, 2000]\n");
  const Recipe r = parse_recipe(
      wall + "installer_scale = 50\ninstaller_paper = \"A1\"\ninstaller_set = \"coursed\"\n",
      "r.toml");
  EXPECT_EQ(r.layout->drawing.installer_scale, 50);
  EXPECT_EQ(r.layout->drawing.installer_paper, "A1");
  EXPECT_EQ(r.layout->drawing.installer_set, InstallerSet::coursed);
  for (const char* bad : {"installer_scale = 7", "installer_scale = 5000", "installer_scale = nan",
                          "installer_paper = \"B4\"", "installer_set = \"fancy\""}) {
    const std::string e = error_of(wall + bad + "\n");
    EXPECT_NE(e.find(std::string(bad).substr(0, std::string(bad).find(' '))), std::string::npos)
        << bad << ": " << e;
  }
  const std::string e = error_of(
      with_layout("kind = \"perforation\"\ncell = [50, 50]\nsheet = [1000, 1000]\ninstaller_set = "
                  "\"coursed\"\n"));
  EXPECT_NE(e.find("\"labelled\""), std::string::npos) << e;
}

// Where layout.gpkg puts the layout: an EPSG code, the datum's easting and northing, the x
// axis's turn; each checked, and refused for an elevation.
TEST(Recipe, Georef) {
  const std::string floor =
      with_layout("kind = \"paving\"\ntile = [600, 300]\nfloor = [12000, 8000]\n");
  const Recipe r =
      parse_recipe(floor +
                       "[layout.georef]\nepsg = 25832\neasting = 500000.5\nnorthing = 5700000\n"
                       "rotation = 12.5\n",
                   "r.toml");
  ASSERT_TRUE(r.layout->georef);
  EXPECT_EQ(r.layout->georef->epsg, 25832);
  EXPECT_EQ(r.layout->georef->easting, 500000.5);
  EXPECT_EQ(r.layout->georef->rotation, 12.5);
  EXPECT_FALSE(parse_recipe(floor, "r.toml").layout->georef);
  for (const char* bad :
       {"epsg = 12", "easting = nan\nepsg = 25832", "epsg = 25832\nrotation = inf",
        "epsg = 25832\nzone = 32", "northing = 1"}) {
    const std::string e = error_of(floor + "[layout.georef]\n" + bad + "\n");
    EXPECT_NE(e.find("layout.georef"), std::string::npos) << bad << ": " << e;
  }
  const std::string e =
      error_of(with_layout("kind = \"facade\"\npanel = [215, 65]\nwall = [4000, 2000]\n") +
               "[layout.georef]\nepsg = 25832\n");
  EXPECT_NE(e.find("elevation"), std::string::npos) << e;
}

TEST(Recipe, Zones) {
  const std::string floor =
      with_layout("kind = \"paving\"\ntile = [600, 300]\nfloor = [12000, 8000]\n");
  const std::string planter = "[[layout.zones]]\nname = \"planter\"\nrule = \"exclude\"\n";
  Recipe r = parse_recipe(floor + planter + "rect = [7000, 3000, 2000, 3000]\n" +
                              "[[layout.zones]]\nname = \"band\"\nrule = \"value\"\nvalue = 1\n"
                              "polygon = [[0, 0], [12000, 0], [6000, 900]]\n",
                          "r.toml");
  ASSERT_EQ(r.layout->zones.size(), 2u);
  EXPECT_EQ(r.layout->zones[0].rects.size(), 1u);
  EXPECT_EQ(r.layout->zones[1].rule, ZoneRule::value);
  EXPECT_EQ(r.layout->zones[1].value, 1u);
  const std::vector<std::pair<std::string, std::string>> wrong = {
      {planter + "rect = [7000, 3000, 9000, 3000]\n", "outside the surface"},
      {planter + "polygon = [[0, 0], [1000, 1000], [1000, 0], [0, 1000]]\n", "simple polygon"},
      {planter + "rect = [0, 0, nan, 10]\n", "layout.zones.0.rect"},
      {planter, "either rect"},
      {"[[layout.zones]]\nname = \"x\"\nrule = \"value\"\nvalue = 9\nrect = [0, 0, 10, 10]\n",
       "layout.zones.0.value"},
      {"[[layout.zones]]\nname = \"x\"\nrule = \"hide\"\nrect = [0, 0, 10, 10]\n", "\"exclude\""},
  };
  for (const auto& [zone, said] : wrong) {
    const std::string e = error_of(floor + zone);
    EXPECT_NE(e.find(said), std::string::npos) << zone << "\n" << e;
  }
}

// The page sends layout.zones = [] when every zone is removed: no zones.
TEST(Recipe, AnEmptyZoneListIsNoZones) {
  const std::string text =
      "[lattice]\nbase = 2\ndimension = 2\n[[curds]]\nprobabilities = [\"3/4\"]\n"
      "[layout]\nkind = \"paving\"\nfloor = [900, 600]\n";
  const Recipe r = parse_recipe(text, "r.toml", {"layout.zones=[]"});
  EXPECT_TRUE(r.layout->zones.empty());
}

TEST(Recipe, Outline) {
  const std::string head = with_layout("kind = \"paving\"\ntile = [600, 300]\n");
  const Recipe r = parse_recipe(
      head +
          "outline = [[0, 0], [12000, 0], [12000, 5000], [8000, 5000], [8000, 8000], [0, 8000]]\n",
      "r.toml");
  ASSERT_TRUE(r.layout->size);
  EXPECT_EQ(*r.layout->size, (std::array<double, 2>{12000, 8000}));
  EXPECT_EQ(r.layout->outline.size(), 6u);
  // Sloping and curved edges are cut along (a triangle here), but not in keep mode.
  EXPECT_EQ(parse_recipe(head + "outline = [[0, 0], [1000, 0], [500, 900]]\n", "r.toml")
                .layout->outline.size(),
            3u);
  EXPECT_NE(error_of(head + "combine = \"keep\"\noutline = [[0, 0], [1000, 0], [500, 900]]\n")
                .find("combine = \"mix\""),
            std::string::npos);
  const std::vector<std::pair<std::string, std::string>> wrong = {
      {"outline = [[-10, 0], [1000, 0], [1000, 900], [-10, 900]]\n", "from 0"},
      {"floor = [500, 500]\noutline = [[0, 0], [1000, 0], [1000, 900], [0, 900]]\n",
       "outside the surface"},
      {"outline = [[0, 0], [1000, 0]]\n", "at least 3 corners"},
      // Points copied from a 3-D model: named as such, not as a bulge out of range.
      {"outline = [[0, 0, 3000], [1000, 0, 3000], [1000, 900, 3000]]\n",
       "reads as 3-D points [x, y, z], every third number 3000"},
      {"outline = [[0, 0, 150], [1000, 0, 150], [1000, 900, 150]]\n", "reads as 3-D points"},
  };
  for (const auto& [text, said] : wrong) {
    const std::string e = error_of(head + text);
    EXPECT_NE(e.find("layout.outline"), std::string::npos) << text << "\n" << e;
    EXPECT_NE(e.find(said), std::string::npos) << text << "\n" << e;
  }
  const std::string e = error_of(head);  // neither a floor nor an outline
  EXPECT_NE(e.find("layout.floor"), std::string::npos) << e;
}

}  // namespace curdle

namespace curdle {
namespace {

std::string site_error(const std::string& text, const RecipeFiles* files) {
  try {
    parse_recipe(text, "r.toml", {}, files);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

// A corner [x, y, bulge] makes the edge to the next an arc: the polygon holds its chords within
// the chord tolerance, the contour the arc, and an arc swelling past the corners sizes the floor.
TEST(Recipe, OutlineArcs) {
  const std::string floor = with_layout("kind = \"paving\"\ntile = [400, 400]\n");
  Recipe r = parse_recipe(
      floor +
          "chord_tolerance = 0.5\noutline = [[0, 0], [10000, 0, 0.2], [10000, 6000], [0, 6000]]\n",
      "r.toml");
  ASSERT_EQ(r.layout->outline_contour.size(), 4u);
  EXPECT_EQ(r.layout->outline_contour[1].bulge, 0.2);
  EXPECT_GT(r.layout->outline.size(), 10u);
  EXPECT_NEAR((*r.layout->size)[0], 10000 + 0.2 * 3000, 1e-6);  // the arc's sagitta beyond x
  EXPECT_DOUBLE_EQ(r.layout->chord_tolerance, 0.5);
  EXPECT_TRUE(parse_recipe(floor + "outline = [[0, 0], [100, 0], [100, 100]]\n", "r.toml")
                  .layout->outline_contour.empty());
  std::string e = error_of(floor + "outline = [[0, 0, 1e9], [100, 0], [100, 100]]\n");
  EXPECT_NE(e.find("bulge"), std::string::npos) << e;
  e = error_of(floor + "outline = [[0, 0, 1], [1000, 0], [1000, 1000]]\n");  // swells below 0
  EXPECT_NE(e.find("from 0"), std::string::npos) << e;
  e = error_of(floor + "chord_tolerance = 0\noutline = [[0, 0], [100, 0], [100, 100]]\n");
  EXPECT_NE(e.find("layout.chord_tolerance"), std::string::npos) << e;
  // A round zone: two half turns.
  r = parse_recipe(floor +
                       "floor = [6000, 6000]\n[[layout.zones]]\nname = \"pit\"\nrule = "
                       "\"exclude\"\npolygon = [[2300, 2500, 1], [3700, 2500, 1]]\n",
                   "r.toml");
  ASSERT_EQ(r.layout->zones.size(), 1u);
  EXPECT_EQ(r.layout->zones[0].contour.size(), 2u);
  EXPECT_GT(r.layout->zones[0].polygon.size(), 16u);
}

TEST(Recipe, SiteFromADrawing) {
  const std::string dxf =
      "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n6\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
      "0\nLWPOLYLINE\n5\n2A\n8\nA-OTLN\n90\n4\n70\n1\n10\n0\n20\n0\n10\n8\n20\n0\n10\n8\n20\n6\n"
      "42\n-0.2\n10\n0\n20\n6\n0\nCIRCLE\n5\n2B\n8\nPIT\n10\n3\n20\n3\n30\n0\n40\n0.5\n"
      "0\nENDSEC\n0\nEOF\n";
  FilesInMemory files;
  files.files["site.dxf"] = dxf;
  const std::string floor = with_layout("kind = \"paving\"\ntile = [400, 400]\n");
  const std::string site = "[layout.site]\nfile = \"site.dxf\"\noutline = \"A-OTLN\"\n";
  const std::string pit = "[[layout.site.zones]]\nlayer = \"PIT\"\nrule = \"exclude\"\n";
  Recipe r = parse_recipe(floor + site + pit, "r.toml", {}, &files);
  EXPECT_EQ(r.layout->outline_contour.size(), 4u);
  EXPECT_EQ((*r.layout->size)[0], 8000);
  EXPECT_EQ((*r.layout->size)[1], 6000);
  ASSERT_EQ(r.layout->zones.size(), 1u);
  EXPECT_EQ(r.layout->zones[0].name, "PIT");
  EXPECT_NE(r.layout->site_summary.find("from site.dxf, units m"), std::string::npos);
  // What the drawing says is refused at layout.site.file, naming the drawing.
  std::string e =
      site_error(floor + "[layout.site]\nfile = \"site.dxf\"\noutline = \"NONE\"\n", &files);
  EXPECT_NE(e.find("layout.site.file"), std::string::npos) << e;
  EXPECT_NE(e.find("layer \"NONE\""), std::string::npos) << e;
  e = site_error(floor + site, nullptr);
  EXPECT_NE(e.find("read only where the recipe is a file"), std::string::npos) << e;
  e = site_error(floor + "outline = [[0, 0], [1, 0], [1, 1]]\n" + site, &files);
  EXPECT_NE(e.find("give one or the other"), std::string::npos) << e;
  e = site_error(floor + "[layout.site]\nfile = \"site.dwg\"\noutline = \"A\"\n", &files);
  EXPECT_NE(e.find(".dxf or .svg file"), std::string::npos) << e;
  e = site_error(floor + site + "units = \"furlong\"\n", &files);
  EXPECT_NE(e.find("layout.site.units"), std::string::npos) << e;
  e = site_error(floor + site + "colour = 3\n", &files);
  EXPECT_NE(e.find("colour"), std::string::npos) << e;
  // The datum: the drawing's origin, the outline's corner, or a point of the drawing.
  EXPECT_EQ(parse_recipe(floor + site + "origin = \"outline\"\n", "r.toml", {}, &files)
                .layout->site_summary.find("outline 8,000 x 6,000 mm"),
            0u);
  e = site_error(floor + site + "origin = [1, \"a\"]\n", &files);
  EXPECT_NE(e.find("layout.site.origin"), std::string::npos) << e;
  // A floor's openings are excluded zones; a perforated sheet takes none.
  r = parse_recipe(floor + site + "openings = \"PIT\"\n", "r.toml", {}, &files);
  ASSERT_EQ(r.layout->zones.size(), 1u);
  EXPECT_EQ(r.layout->zones[0].name, "opening 1");
}

// A building's plan from a layer of a drawing (the kiosk's, its south front an arc), and a
// façade's windows and door from its elevation (the 12 m brick elevation's INSERTs).
TEST(Recipe, ABuildingsPlanAndOpeningsFromDrawings) {
  FilesInMemory files;
  for (const char* name : {"kiosk.dxf", "elevation.dxf"}) {
    std::ifstream in(std::string(CURDLE_SOURCE_DIR) + "/patterns/sites/" + name, std::ios::binary);
    files.files[name] = std::string(std::istreambuf_iterator<char>(in), {});
  }
  const std::string bricks = with_layout("kind = \"facade\"\npanel = [215, 65]\njoint = 10\n");
  const Recipe kiosk = parse_recipe(bricks + R"([layout.building]
height = 3000
[layout.building.site]
file = "kiosk.dxf"
plan = "A-WALL"
)",
                                    "r.toml", {}, &files);
  const BuildingKeys& k = *kiosk.layout->own<FacadeKeys>().building;
  ASSERT_EQ(k.plan.size(), 4u);
  EXPECT_NEAR(k.plan[0].bulge, 0.2, 1e-9);  // the front's arc kept
  EXPECT_NE(kiosk.layout->site_summary.find("1 arc"), std::string::npos);
  // A hall whose south front, `width` mm long, has the elevation's windows and door.
  auto hall_of = [&](int width) {
    return bricks + "[layout.building]\nplan = [[0, 0], [" + std::to_string(width) + ", 0], [" +
           std::to_string(width) + R"(, 8000], [0, 8000]]
height = 6300
[[layout.building.elevations]]
facade = "S"
file = "elevation.dxf"
wall = "A-WALL"
openings = ["A-GLAZ", "A-DOOR"]
)";
  };
  const Recipe hall = parse_recipe(hall_of(12000), "r.toml", {}, &files);
  const Envelope& env = *hall.layout->own<FacadeKeys>().envelope;
  ASSERT_EQ(env.openings.size(), 8u);  // seven windows and the door
  size_t doors = 0;
  for (size_t i = 0; i < env.openings.size(); ++i) {
    EXPECT_EQ(env.opening_facade[i], 0u);
    doors += env.opening_type[i] == "door";
  }
  EXPECT_EQ(doors, 1u);
  EXPECT_NE(site_error(hall_of(9000), &files).find("past its corner at 9000 mm"),
            std::string::npos);
}

}  // namespace curdle

namespace curdle {

// Storeys of different heights and a bond of headers: read into the building and its drawings;
// both ways of giving storeys at once, storeys taller than the wall and English bond on a flat
// wall refused.
TEST(Recipe, ABuildingsStoreysAndBond) {
  const std::string bricks =
      with_layout("kind = \"facade\"\npanel = [215, 65]\njoint = 10\nbond = \"english\"\n");
  const std::string building = R"([layout.building]
plan = [[0, 0], [9000, 0], [9000, 6000], [0, 6000]]
height = 7050
)";
  const Recipe r = parse_recipe(bricks + building + "storeys = [4200, 2850]\n", "r.toml");
  EXPECT_EQ(r.layout->own<FacadeKeys>().building->storeys, (std::vector<double>{4200, 2850}));
  EXPECT_EQ(r.layout->drawing.storeys, (std::vector<double>{4200, 2850}));
  EXPECT_EQ(r.layout->own<FacadeKeys>().bond, CourseBond::english);
  EXPECT_NE(site_error(bricks + building + "storey = 3000\nstoreys = [4200]\n", nullptr)
                .find("cannot be given with `storey`"),
            std::string::npos);
  EXPECT_NE(site_error(bricks + building + "storeys = [4200, 4200]\n", nullptr)
                .find("add up to 8400 mm, more than the wall's height (7050 mm)"),
            std::string::npos);
  EXPECT_NE(site_error(bricks + building + "storeys = [200]\n", nullptr).find("at least 1000"),
            std::string::npos);
  EXPECT_NE(
      site_error(bricks + building + "arcs = \"wavy\"\n", nullptr).find("\"bent\" (units bent"),
      std::string::npos);
  EXPECT_TRUE(parse_recipe(bricks + building + "arcs = \"bent\"\n", "r.toml")
                  .layout->own<FacadeKeys>()
                  .building->bent_on_arcs);
  EXPECT_EQ(
      parse_recipe(bricks + building + "wall = \"one-brick\"\nbacking = \"Commons\"\n", "r.toml")
          .layout->own<FacadeKeys>()
          .building->backing,
      "Commons");
  EXPECT_NE(site_error(bricks + building + "wall = \"double\"\n", nullptr).find("\"one-brick\""),
            std::string::npos);
  EXPECT_NE(site_error(bricks + building + "backing = \"Commons\"\n", nullptr)
                .find("a half-brick or cavity leaf has none"),
            std::string::npos);
  EXPECT_NE(site_error(with_layout("kind = \"facade\"\npanel = [215, 65]\nwall = [2000, 975]\n"
                                   "bond = \"flemish\"\n"),
                       nullptr)
                .find("round a building ([layout.building]) only"),
            std::string::npos);
}

// A rule's windows left out and replaced by name: read into the building; names that are not
// a rule's window refused saying what is.
TEST(Recipe, ARulesWindowsOmittedAndReplacedByName) {
  const std::string recipe =
      with_layout("kind = \"facade\"\npanel = [215, 65]\njoint = 10\n") + R"([layout.building]
plan = [[0, 0], [9000, 0], [9000, 6000], [0, 6000]]
height = 3000
[[layout.building.openings]]
replaces = "W-2"
rect = [3000, 0, 1000, 2100]
type = "door"
[layout.building.windows]
size = [1200, 1500]
every = 3000
clear = 900
sill = 900
)";
  const Recipe r = parse_recipe(recipe + "omit = [\"W-1\"]\n", "r.toml");
  const BuildingKeys& b = *r.layout->own<FacadeKeys>().building;
  EXPECT_EQ(b.windows->omit, (std::vector<std::string>{"W-1"}));
  EXPECT_EQ(b.openings.at(0).replaces, "W-2");
  EXPECT_NE(site_error(recipe + "omit = [\"D-1\"]\n", nullptr).find("[\"W-3\", \"W-17\"]"),
            std::string::npos);
  EXPECT_NE(site_error(recipe + "omit = [\"W-50\"]\n", nullptr)
                .find("W-50, which is not a window of the rule: it sets W-1 to W-"),
            std::string::npos);
}

// An arc by its centre after the vertex it starts from, as a setter-out gives it: the sweep in
// degrees or the length along the arc, positive anticlockwise; the same bulge and end as the
// bulge's form. A radius that is not the distance to the centre, both sweep and length, an
// arc first and an unknown key are refused saying what is allowed.
TEST(Recipe, AnArcByItsCentreRadiusAndSweepOrLength) {
  const std::string bricks = with_layout("kind = \"facade\"\npanel = [215, 65]\njoint = 10\n");
  auto wall = [&](const std::string& path) {
    return bricks + "[layout.building]\nheight = 2400\npath = " + path + "\n";
  };
  const Recipe swept =
      parse_recipe(wall("[[0, 0], { centre = [0, 12000], sweep = 90 }]"), "r.toml");
  const Contour& p = swept.layout->own<FacadeKeys>().building->path;
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[0].bulge, std::tan(std::numbers::pi / 8), 1e-12);
  EXPECT_NEAR(p[1].x, 12000, 1e-9);
  EXPECT_NEAR(p[1].y, 12000, 1e-9);
  const Recipe along = parse_recipe(
      wall("[[0, 0], { centre = [0, 12000], length = 18000, radius = 12000 }]"), "r.toml");
  const Contour& q = along.layout->own<FacadeKeys>().building->path;
  EXPECT_NEAR(q[0].bulge, std::tan(1.5 / 4), 1e-12);
  EXPECT_NEAR(arc_between(q[0], q[1]).radius, 12000, 1e-6);
  const Recipe clockwise =
      parse_recipe(wall("[[0, 0], { centre = [0, -5000], sweep = -30 }, [9000, 0]]"), "r.toml");
  EXPECT_LT(clockwise.layout->own<FacadeKeys>().building->path[0].bulge, 0);
  EXPECT_EQ(clockwise.layout->own<FacadeKeys>().building->path.size(), 3u);

  EXPECT_NE(
      site_error(wall("[[0, 0], { centre = [0, 12000], sweep = 90, radius = 11000 }]"), nullptr)
          .find("lies 12000.0 mm from that centre"),
      std::string::npos);
  for (const char* bad : {"[[0, 0], { centre = [0, 12000], sweep = 90, length = 100 }]",
                          "[{ centre = [0, 12000], sweep = 90 }, [5, 5]]",
                          "[[0, 0], { centre = [0, 12000], sweep = 360 }]",
                          "[[0, 0], { centre = [0, 12000], turn = 90 }]",
                          "[[0, 0], { centre = [0, nan], sweep = 90 }]"})
    EXPECT_NE(site_error(wall(bad), nullptr).find("centre = [x, y]"), std::string::npos) << bad;
}

}  // namespace curdle
