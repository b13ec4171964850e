// Tests of zone_in_cells.h.
#include "app/zone_in_cells.h"

#include <gtest/gtest.h>

#include "outputs_support.h"

namespace fs = std::filesystem;

namespace curdle::app {
TEST(SearchZones, MillimetresBecomeTheCellsLaidThere) {
  RunRequest request;
  request.recipe_path = std::string(CURDLE_SOURCE_DIR) + "/patterns/paper/fig7-paving-20m.toml";
  request.recipe_text = read_recipe_file(request.recipe_path);
  app::Run run = resolve_run(request);  // 300 mm tiles, no joint, from the bottom-left
  EXPECT_EQ(zone_in_cells("empty=0,0,900,600mm", run), "empty=0,0,3,2");
  EXPECT_EQ(zone_in_cells("empty:dark=1000,0,1000,300 mm", run), "empty:dark=3,0,4,1");
  EXPECT_EQ(zone_in_cells("empty=0,0,3,2", run), "empty=0,0,3,2");  // cells stay cells
  EXPECT_EQ(zone_in_cells("ratio:dark=0.1", run), "ratio:dark=0.1");
  request.overrides = {"layout.origin=\"top-right\""};
  run = resolve_run(request);  // laid from the top right: the 200 mm cut pieces are at x, y = 0
  EXPECT_EQ(zone_in_cells("empty=0,0,900,600mm", run), "empty=0,0,4,3");
  EXPECT_EQ(zone_in_cells("empty=200,200,900,600mm", run), "empty=1,1,3,2");
  for (const char* bad :
       {"empty=0,0,0,600mm", "empty=0,0,nan,600mm", "empty=0,0,600mm", "empty=30000,0,100,100mm",
        "empty=0,0,1e308,10 mm", "empty=-100,0,300,300 mm", "empty=19900,0,300,300 mm"}) {
    try {
      zone_in_cells(bad, run);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("target"), std::string::npos) << e.what();
    }
  }
}

}  // namespace curdle::app
