#include "site/dxf_blocks.h"

#include <gtest/gtest.h>

namespace curdle::site {
namespace {

Shape square(const std::string& layer) {
  Shape s;
  s.layer = layer;
  s.entity = "LWPOLYLINE";
  s.path = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
  s.closed = true;
  return s;
}

// An array of a block on layer 0 takes the INSERT's layer and handle; a block never defined is
// named, not placed.
TEST(DxfBlocksTest, ArraysTakeTheInsertsLayerAndMissingBlocksAreNamed) {
  std::map<std::string, Block> blocks;
  blocks["PIT"].shapes.push_back(square("0"));
  Insert i;
  i.block = "PIT", i.layer = "L-PLNT-PITS", i.handle = "2F";
  i.x = 100, i.y = 50, i.columns = 3, i.column_spacing = 20;
  blocks[""].inserts.push_back(i);
  Insert lost = i;
  lost.block = "GONE";
  blocks[""].inserts.push_back(lost);
  Drawing d;
  const std::set<std::string> missing = place_blocks(blocks, "site.dxf", 0.01, d);
  EXPECT_EQ(missing, std::set<std::string>{"GONE"});
  ASSERT_EQ(d.shapes.size(), 3u);
  EXPECT_EQ(d.shapes[2].layer, "L-PLNT-PITS");
  EXPECT_EQ(d.shapes[2].insert_handle, "2F");
  EXPECT_NEAR(d.shapes[2].path[0].x, 140, 1e-9);
  EXPECT_NEAR(d.shapes[2].path[0].y, 50, 1e-9);
}

TEST(DxfBlocksTest, PlacementsAreCountedEvenOfEmptyBlocks) {
  std::map<std::string, Block> blocks;
  blocks["EMPTY"];
  Insert row;
  row.block = "EMPTY", row.columns = 400, row.rows = 400;
  blocks["ROW"].inserts.push_back(row);
  Insert grid = row;
  grid.block = "ROW";
  blocks[""].inserts.push_back(grid);
  Drawing d;
  try {
    place_blocks(blocks, "site.dxf", 0.01, d);
    ADD_FAILURE() << "placed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1000000 block placements"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace curdle::site
