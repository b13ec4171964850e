#include "site/dxf_hatch.h"

#include <gtest/gtest.h>

#include <cmath>

#include "dxf_groups_support.h"
#include "site/drawing.h"

namespace curdle::site {
namespace {

using testing::EntityGroups;

TEST(DxfHatchTest, PolylineAndEdgePathsAreClosedContours) {
  const EntityGroups e(
      "91\n2\n"
      // A polyline path: a 100 square.
      "92\n3\n72\n0\n73\n1\n93\n4\n10\n0\n20\n0\n10\n100\n20\n0\n10\n100\n20\n100\n10\n0\n20\n"
      "100\n97\n0\n"
      // Edges: a line, a clockwise half circle up the east side, turning west into the square
      // (its angles stored mirrored, as ezdxf reads them), a line back.
      "92\n1\n93\n3\n72\n1\n10\n200\n20\n0\n11\n300\n21\n0\n"
      "72\n2\n10\n300\n20\n50\n40\n50\n50\n90\n51\n270\n73\n0\n"
      "72\n1\n10\n300\n20\n100\n11\n200\n21\n100\n97\n0\n75\n0\n");
  const auto b = hatch_boundaries(e.groups, e.numbers, "HATCH 60", "L-PAVE", 0.01);
  ASSERT_TRUE(b);
  ASSERT_EQ(b->loops.size(), 2u);
  EXPECT_NEAR(contour_area(b->loops[0]), 10000, 1e-9);
  // 100 x 100 less the half disc of radius 50 the clockwise arc cuts in from x = 300.
  EXPECT_NEAR(contour_area(b->loops[1]), 10000 - 3.14159265358979323846 * 2500 / 2, 1e-6);
  EXPECT_NEAR(contour_bounds(b->loops[1]).right(), 300, 1e-9);
}

TEST(DxfHatchTest, APathWithoutItsGroupsIsRefusedByName) {
  const EntityGroups none("2\nSOLID\n");
  EXPECT_FALSE(hatch_boundaries(none.groups, none.numbers, "HATCH 60", "L", 0.01));
  const EntityGroups cut("91\n1\n92\n2\n72\n0\n73\n1\n");
  try {
    hatch_boundaries(cut.groups, cut.numbers, "HATCH 60", "L-PAVE", 0.01);
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the HATCH 60 on layer \"L-PAVE\" has a boundary path "
                                         "without group 93"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace curdle::site
