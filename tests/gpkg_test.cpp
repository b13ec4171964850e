// layout.gpkg as written: a GeoPackage (an SQLite file) with a table per kind of element; a
// recipe's CRS that is not projected in metres is refused by name. GDAL reads every pattern's
// back in tests/gpkg_read_back.py.
#include "export/gis/gpkg.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "app/outputs.h"
#include "app/run.h"
#include "curdle/error.h"
#include "layout/builder.h"
#include "picture_support.h"
#include "test_support.h"

namespace curdle {
namespace {

Layout park() {
  const std::string path = std::string(CURDLE_SOURCE_DIR) + "/patterns/paper/fig5a-park.toml";
  const app::Run run = test::run_recipe(path, app::read_recipe_file(path), {});
  return make_layout(run.recipe.design, app::run_engine(run, 0), run.view, *run.recipe.layout);
}

TEST(Gpkg, WritesAGeoPackageWithATablePerKind) {
  std::string why;
  ASSERT_TRUE(gpkg_installed(&why)) << why;
  const auto dir = test::scratch("gpkg");
  write_layout_gpkg(dir / "layout.gpkg", park());
  std::ifstream in(dir / "layout.gpkg", std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  const std::string file = bytes.str();
  EXPECT_EQ(file.rfind("SQLite format 3", 0), 0u);
  for (const char* table : {"white_paving", "tree", "bench", "gpkg_contents"})
    EXPECT_NE(file.find(table), std::string::npos) << table;
  // The same run gives the same bytes: GDAL's time stamps are fixed.
  write_layout_gpkg(dir / "again.gpkg", park());
  std::ifstream again(dir / "again.gpkg", std::ios::binary);
  std::stringstream again_bytes;
  again_bytes << again.rdbuf();
  EXPECT_TRUE(again_bytes.str() == file);
  std::filesystem::remove_all(dir);
}

// The server's downloads and the Python module's bytes go through a sink in memory.
TEST(Gpkg, IsWrittenThroughASinkInMemory) {
  const std::string path = std::string(CURDLE_SOURCE_DIR) + "/patterns/courtyard-l-shaped.toml";
  const app::Run run = test::run_recipe(path, app::read_recipe_file(path), {});
  app::MemorySink sink;
  app::write_outputs(run, app::select_outputs(run, {"layout.gpkg"}, nullptr), sink, 0, nullptr);
  EXPECT_EQ(sink.files().at("layout.gpkg").rfind("SQLite format 3", 0), 0u);
}

TEST(Gpkg, ACrsThatIsNotProjectedInMetresIsRefusedByName) {
  Layout layout = park();
  const auto dir = test::scratch("gpkg-crs");
  layout.georef = Georef{4326, 0, 0, 0};
  try {
    write_layout_gpkg(dir / "a.gpkg", layout);
    FAIL() << "EPSG:4326 taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "layout.georef.epsg");
    EXPECT_NE(e.message().find("EPSG:4326 is a geographic CRS (it measures in degrees)"),
              std::string::npos)
        << e.message();
  }
  layout.georef = Georef{9999, 0, 0, 0};
  EXPECT_THROW(write_layout_gpkg(dir / "b.gpkg", layout), InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curdle
