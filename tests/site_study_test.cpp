#include "app/site_study.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "curdle/error.h"
#include "dxf_text.h"

namespace curdle::app {
namespace {

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

app::Run courtyard_run() {
  RunRequest request;
  // Appended, not summed: GCC 12 warns falsely on `std::string(...) + "..."`.
  request.recipe_path = std::string(CURDLE_SOURCE_DIR).append("/patterns/courtyard-l-shaped.toml");
  request.recipe_text = file_text(request.recipe_path);
  return resolve_run(request);
}

SiteStudyRequest drawing(const std::string& name) {
  SiteStudyRequest r;
  r.name = name;
  r.bytes = file_text(std::string(CURDLE_SOURCE_DIR).append("/patterns/sites/").append(name));
  return r;
}

TEST(SiteStudyTest, ListsTheLayersThenReadsTheChosenOnes) {
  const app::Run run = courtyard_run();
  SiteStudyRequest r = drawing("courtyard.dxf");
  const auto listed = study_site(run, r);
  EXPECT_EQ(listed["format"], "DXF");
  EXPECT_EQ(listed["layers"].size(), 3u);
  EXPECT_EQ(listed["layers"][1]["name"], "TREE_PIT");
  EXPECT_FALSE(listed.contains("site"));
  r.outline = "A-OTLN";
  r.zones = {"TREE_PIT", "DRAIN"};
  const auto read = study_site(run, r);
  const auto& site = read["site"];
  EXPECT_EQ(site["sets"][0],
            "layout.outline=[[0,0],[14000,0],[14000,9000,-0.20000000000000001],[4000,9000],"
            "[4000,7000],[0,7000]]");
  ASSERT_EQ(site["zones"].size(), 2u);
  EXPECT_EQ(site["zones"][0]["polygon"].size(), 2u);  // the pit: two half turns
  // The keys lay: the run with them and the zones takes the drawing's courtyard.
  RunRequest again;
  again.recipe_path = run.recipe_path;
  again.recipe_text = run.recipe_text;
  again.overrides = {site["sets"][0].template get<std::string>()};
  const app::Run laid = resolve_run(again);
  EXPECT_EQ((*laid.recipe.layout->size)[0], 14000);
  EXPECT_EQ(laid.recipe.layout->outline_contour.size(), 6u);
}

TEST(SiteStudyTest, AFacadeTakesRectangularOpeningsAsWindows) {
  RunRequest request;
  request.recipe_path =
      std::string(CURDLE_SOURCE_DIR) + "/patterns/brick-facade-stretcher-bond.toml";
  request.recipe_text = file_text(request.recipe_path);
  SiteStudyRequest r = drawing("elevation.dxf");
  r.outline = "A-WALL";
  r.openings = {"A-GLAZ", "A-DOOR"};
  const auto site = study_site(resolve_run(request), r)["site"];
  ASSERT_EQ(site["sets"].size(), 2u);
  EXPECT_EQ(site["sets"][1].get<std::string>().rfind("layout.openings=[[1500,900,1200,1500],", 0),
            0u)
      << site["sets"][1];
  EXPECT_TRUE(site["zones"].empty());
}

// Two plots side by side on one layer: the listing shows both regions in drawing coordinates,
// the read refuses to choose, and a click inside one (the page's `around`) picks it.
TEST(SiteStudyTest, AClickInsideARegionPicksTheOutline) {
  const app::Run run = courtyard_run();
  SiteStudyRequest r;
  r.name = "plots.dxf";
  r.bytes = testing::DxfText(6)
                .begin_entities_only()
                .lwpolyline("A-SITE", "1A",
                            {{{100, 50, 0}, {112, 50, 0}, {112, 58, 0}, {100, 58, 0}}}, true)
                .lwpolyline("A-SITE", "1B",
                            {{{120, 50, 0}, {134, 50, 0}, {134, 59, 0}, {120, 59, 0}}}, true)
                .text();
  const auto listed = study_site(run, r);
  ASSERT_EQ(listed["regions"].size(), 1u);
  EXPECT_EQ(listed["regions"][0]["layer"], "A-SITE");
  ASSERT_EQ(listed["regions"][0]["rings"].size(), 2u);
  EXPECT_EQ(listed["regions"][0]["rings"][1][0][0], 120);  // metres, as drawn
  r.outline = "A-SITE";
  EXPECT_THROW(study_site(run, r), InputError);
  r.around = "127,55.5";
  const auto read = study_site(run, r);
  // The drawing's origin is the datum: the plot lies in its first quadrant.
  EXPECT_EQ(read["site"]["sets"][0],
            "layout.outline=[[120000,50000],[134000,50000],[134000,59000],[120000,59000]]");
  for (const std::string bad : {"127", "127,", "127,x", "1e999,2", "nan,2", "1,2,3", ",2"}) {
    r.around = bad;
    try {
      study_site(run, r);
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("around"), std::string::npos) << e.what();
    }
  }
}

// An upload that could take more memory to read than the server allows is refused before it is
// parsed, naming the limit and how to raise it.
TEST(SiteStudyTest, ADrawingTooLargeForTheMemoryLimitIsRefusedUnread) {
  app::Run run = courtyard_run();
  run.generate.max_memory_bytes = 1 << 20;
  run.generate.memory_limit_hint = "start the server with a larger --max-memory";
  SiteStudyRequest r;
  r.name = "paths.svg";
  r.bytes = "<svg xmlns=\"http://www.w3.org/2000/svg\">";
  for (int i = 0; i < 2000; ++i) r.bytes += "<path d=\"M0 0L1 1Z\"/>";
  r.bytes += "</svg>";
  try {
    study_site(run, r);
    FAIL() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "above the memory limit of 1.0 MiB; start the server with a larger --max-memory"),
              std::string::npos)
        << e.what();
  }
}

TEST(SiteStudyTest, RefusesWithTheDrawingsMessage) {
  const app::Run run = courtyard_run();
  SiteStudyRequest r;
  r.name = "site.dxf";
  r.bytes = "not a drawing";
  try {
    study_site(run, r);
    FAIL() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a DXF drawing"), std::string::npos) << e.what();
  }
  r = drawing("courtyard.dxf");
  r.outline = "NOPE";
  EXPECT_THROW(study_site(run, r), InputError);
  r.name = "site.png";
  EXPECT_THROW(study_site(run, r), InputError);
}

}  // namespace
}  // namespace curdle::app
