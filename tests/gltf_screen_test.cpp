// Tests of gltf_screen.h: a screen on a building as glTF nodes, one a sheet with its tiles.
#include "export/gltf/gltf_screen.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "building_support.h"
#include "layout/framed_sheet.h"

namespace curdle {
namespace {

TEST(GltfScreen, ANodeASheetAndAMeshAShape) {
  std::ifstream in(std::string(CURDLE_SOURCE_DIR) + "/patterns/perforated-screen-curved.toml");
  std::stringstream text;
  text << in.rdbuf();
  const Layout l = test::lay_recipe(text.str());
  ModelBuilder b;
  b.model.materials.emplace_back();
  const std::vector<int> sheets = add_screen_sheets(b, l, 0);
  ASSERT_EQ(sheets.size(), l.sheets().size());
  EXPECT_EQ(std::set<int>(sheets.begin(), sheets.end()).size(), sheets.size());
  // A mesh per sheet, named by its ID, and one per shape of tile: the screen's 4,824 openings
  // come in a few diameters and merged shapes, not a mesh each.
  std::set<std::string> names;
  size_t tile_meshes = 0;
  for (const tinygltf::Mesh& m : b.model.meshes) {
    if (m.name.rfind("sheet round opening", 0) == 0) ++tile_meshes;
    names.insert(m.name);
  }
  for (const FabricationSheet& s : l.sheets()) EXPECT_TRUE(names.count("sheet " + s.id)) << s.id;
  EXPECT_GT(tile_meshes, 0u);
  EXPECT_LT(tile_meshes, 100u);
  size_t tiled = 0;
  for (const auto& on_sheet : framed_screen(l).tiled) tiled += on_sheet.size();
  EXPECT_EQ(b.model.meshes.size(), l.sheets().size() + tile_meshes);
  EXPECT_GT(tiled, 4000u) << "each opening is placed as a node of its sheet";
}

}  // namespace
}  // namespace curdle
