// Tests of title_block.h: the title block names the recipe, seed, lattice and probabilities,
// and the kind says the surface and how it is laid; legends count in the kind's unit.
#include "layout/title_block.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
namespace {

TEST(TitleBlock, SaysWhatWasLaidFromWhatAndCountsInTheKindsUnit) {
  Design d = test::design(2, 2, {{"3/4", "2/3"}});
  d.name = "forecourt";
  d.description = "south entrance";
  LayoutSpec spec = test::layout_spec("paving");
  spec.module_w = spec.module_h = 400, spec.joint = 10;
  spec.size = std::array<double, 2>{1800, 1200};
  spec.bond = 0.5;
  const Layout paving = lay_floor(d, spec, 17);
  const std::vector<std::string> lines = title_lines(paving);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "forecourt - south entrance");
  EXPECT_EQ(lines[1], "seed 17 - base 2, 2-D, 2 stages, canonical mode");
  EXPECT_EQ(lines[2], "probabilities: c0 3/4, 2/3");
  EXPECT_EQ(lines[3].rfind("1800 x 1200 mm: ", 0), 0u) << lines[3];
  EXPECT_NE(lines[3].find("paving tiles of 400 x 400 mm, joint 10 mm"), std::string::npos);
  EXPECT_EQ(lines[4], "origin bottom-left; half bond; element IDs count rows and columns from it");
  EXPECT_EQ(segment_text(paving), "");  // the whole field
  Layout segment = paving;
  segment.source.field = Box{{0, 0, 0}, {64, 32, 1}};
  segment.view = Box{{8, 4, 0}, {5, 3, 1}};
  EXPECT_EQ(title_lines(segment)[1],
            "seed 17, window 8,4,5,3 of the 64 x 32 field - base 2, 2-D, 2 stages, canonical mode");
  EXPECT_EQ(legend_count(paving, 1), "1 paving tile");
  EXPECT_EQ(legend_count(paving, 3), "3 paving tiles");

  LayoutSpec sheet = test::layout_spec("perforation");
  sheet.size = std::array<double, 2>{1200, 600};
  sheet.own<PerforationKeys>().thickness = 3;
  sheet.own<PerforationKeys>().holes = {{100, 0, 0}};
  const Layout perforated = lay_floor(d, sheet, 17);
  const std::vector<std::string> sheet_lines = title_lines(perforated);
  EXPECT_EQ(sheet_lines[3].rfind("1200 x 600 mm sheet: 4 x 2 cells of 300 x 300 mm", 0), 0u)
      << sheet_lines[3];
  EXPECT_EQ(sheet_lines[4].rfind("sheet 3 mm thick, ", 0), 0u) << sheet_lines[4];
  EXPECT_EQ(legend_count(perforated, 2), "2 openings");  // the legend counts what is punched
}

}  // namespace
}  // namespace curdle
