// Tests of element_id.h: IDs as every output writes them.
#include "layout/element_id.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(ElementId, RowsColumnsLevelsAndPartsAreWrittenOneWay) {
  const ElementId tile{'P', 2, std::nullopt, 3, 4, ""};
  EXPECT_EQ(tile.text(), "P-R03-C04");
  EXPECT_EQ(tile.within('H', "2").text(), "H-R03-C04-2");
  EXPECT_EQ(tile.within('K', "tree").text(), "K-R03-C04-tree");
  EXPECT_EQ(tile.as('R').text(), "R-R03-C04");
  EXPECT_EQ((ElementId{'B', 2, 1, 2, 3, ""}).text(), "B-L01-R02-C03");
  EXPECT_EQ((ElementId{'T', 4, std::nullopt, 12, 345, ""}).text(), "T-R0012-C0345");
}

}  // namespace
}  // namespace curdle
