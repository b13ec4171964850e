// Tests of guidance.h.
#include "layout/guidance.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
using test::design;

TEST(Layout, LargeFirstStageCellsAreWarnedOf) {
  auto notes_for = [](int base, int stages) {
    std::vector<std::string> probabilities(static_cast<size_t>(stages), "3/4");
    const Design d = design(base, 2, {probabilities});
    LayoutSpec spec = test::layout_spec();
    spec.set_kind(layout_kind("paving"));
    spec.module_w = 300, spec.module_h = 300;
    spec.size = std::array<double, 2>{9700, 4900};
    return lay_floor(d, spec, 2).notes;
  };
  const auto warned = notes_for(4, 3);  // first-stage cells 16 elements, 4.8 m, on a 4.9 m floor
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_NE(warned[0].find("4.80 x 4.80 m"), std::string::npos) << warned[0];
  EXPECT_NE(warned[0].find("base 2 and at most 3 stages"), std::string::npos) << warned[0];
  EXPECT_TRUE(notes_for(2, 3).empty());  // 4 elements, 1.2 m: fits
}

// A first stage at p = 1 keeps every cell: the warning is of the first stage where one can die.
TEST(Layout, TheWarningIsOfTheFirstStageWhereACellCanDie) {
  auto notes_for = [](std::vector<std::string> probabilities) {
    const Design d = design(4, 2, {probabilities});
    LayoutSpec spec = test::layout_spec();
    spec.set_kind(layout_kind("paving"));
    spec.module_w = 300, spec.module_h = 300;
    spec.size = std::array<double, 2>{9700, 4900};
    return lay_floor(d, spec, 2).notes;
  };
  EXPECT_TRUE(notes_for({"1", "3/4", "3/4"}).empty());        // stage 2's cells: 4 elements, 1.2 m
  EXPECT_TRUE(notes_for({"1", "1", "1"}).empty());            // nothing dies
  const auto second = notes_for({"1", "3/4", "3/4", "3/4"});  // stage 2's: 16 elements
  ASSERT_EQ(second.size(), 1u);
  EXPECT_NE(second[0].find("stage 2's (the first where a cell can die) cells are 4.80 x 4.80 m"),
            std::string::npos)
      << second[0];
  const auto late = notes_for({"3/4", "1", "1"});
  ASSERT_EQ(late.size(), 1u);
  EXPECT_NE(late[0].find("the first stage's cells are 4.80 x 4.80 m"), std::string::npos);
}

}  // namespace curdle
