// Tests of punching.h: the order list has a row per fabrication sheet with its stock and the
// hits of each punch, and a total that adds them up to the openings of the schedule.
#include "export/schedules/punching.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

#include "building_support.h"
#include "export_support.h"
#include "kinds/perforation.h"
#include "layout_support.h"

namespace curdle {
namespace {

TEST(Punching, ARowPerSheetWithItsStockAndHitsAndATotal) {
  Design d = test::design(4, 2, {{"3/4", "3/4"}, {"1/2", "3/4"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("perforation"));
  spec.module_w = spec.module_h = 40;
  spec.size = std::array<double, 2>{640, 640};
  spec.outline = {{0, 0}, {640, 0}, {640, 400}, {320, 640}, {0, 400}};
  PerforationKeys& keys = spec.own<PerforationKeys>();
  keys.holes = {{16, -8, 0}, {12, 8, 0}};
  keys.thickness = 3;
  keys.edge_margin = 4;
  keys.sheet_size = std::array<double, 2>{320, 320};
  keys.sheet_material = "Aluminium 5005, anodised";
  const Layout layout = lay_floor(d, spec, 3);
  std::ostringstream out;
  write_punching_csv(out, layout);
  const auto rows = strict_csv(out.str().substr(3));
  ASSERT_EQ(rows.size(), layout.sheets().size() + 2);  // header, sheets, total
  EXPECT_EQ(rows[0][0], "sheet_id");
  EXPECT_EQ(rows[0][8], "hits_D12");
  EXPECT_EQ(rows[0][9], "hits_D16");
  std::map<std::string, uint64_t> openings;  // per punch, from the elements
  for (const Element& e : layout.elements)
    if (e.circle) ++openings[e.circle->d == 12 ? "hits_D12" : "hits_D16"];
  const auto& total = rows.back();
  EXPECT_EQ(total[0], "total");
  double area = 0;
  for (size_t r = 1; r + 1 < rows.size(); ++r) {
    EXPECT_EQ(rows[r][0], layout.sheets()[r - 1].id);
    EXPECT_EQ(rows[r][1], "Aluminium 5005, anodised");  // quoted in the file: it holds a comma
    EXPECT_EQ(rows[r][2], "3");
    EXPECT_EQ(rows[r][3] + " x " + rows[r][4], "320 x 320");
    // A sheet the outline cuts leaves more offcut; every sheet's adds to its stock.
    EXPECT_NEAR(std::stod(rows[r][5]) + std::stod(rows[r][6]), 0.1024, 1e-6);
    area += std::stod(rows[r][5]);
  }
  EXPECT_NEAR(std::stod(total[5]), area, 1e-6);
  // The hits, then each sheet's blank: a flat sheet's is the sheet, on no façade, not rolled.
  const size_t blank = rows[0].size() - 4;
  EXPECT_EQ(rows[0][blank], "facade");
  EXPECT_EQ(rows[0][blank + 1], "blank_width_mm");
  EXPECT_EQ(rows[0][blank + 3], "bend_radius_mm");
  for (size_t r = 1; r + 1 < rows.size(); ++r) {
    EXPECT_EQ(rows[r][blank], "");
    EXPECT_NEAR(std::stod(rows[r][blank + 1]), layout.sheets()[r - 1].area.w, 0.005);
    EXPECT_NEAR(std::stod(rows[r][blank + 2]), layout.sheets()[r - 1].area.h, 0.005);
    EXPECT_EQ(rows[r][blank + 3], "");
  }
  for (size_t c = 8; c < blank; ++c) {
    uint64_t sum = 0;
    for (size_t r = 1; r + 1 < rows.size(); ++r) sum += std::stoull(rows[r][c]);
    EXPECT_EQ(std::stoull(total[c]), sum) << rows[0][c];
    if (openings.count(rows[0][c])) {
      EXPECT_EQ(sum, openings[rows[0][c]]) << rows[0][c];
    }
  }
}

// A screen along a curve: its sheets cut within each leg, those on the arc rolled to it, their
// blanks developed at mid-thickness.
TEST(Punching, ARolledSheetsBlankIsDevelopedAtMidThicknessWithItsBendRadius) {
  const Layout layout = test::lay_recipe(test::screen_recipe(
      "sheet_size = [1250, 2500]\n", "[[0, 0], { centre = [0, 8000], sweep = 30 }, [4000, 3000]]"));
  std::ostringstream out;
  write_punching_csv(out, layout);
  const auto rows = strict_csv(out.str().substr(3));
  const double arc = 8000 * M_PI / 6;  // 4188.8 mm: four sheets of a quarter of it
  ASSERT_GE(rows.size(), 7u);
  const size_t blank = rows[0].size() - 4;
  ASSERT_EQ(layout.frames().size(), 2u);
  const std::string arc_facade = layout.frames()[0].name, straight = layout.frames()[1].name;
  EXPECT_EQ(rows[1][0], "S-" + arc_facade + "-R1-C1");
  EXPECT_EQ(rows[1][blank], arc_facade);
  EXPECT_NEAR(std::stod(rows[1][blank + 1]), arc / 4 * (8000 - 1.5) / 8000, 0.005);
  EXPECT_NEAR(std::stod(rows[1][blank + 2]), 1600, 1e-9);
  EXPECT_EQ(rows[1][blank + 3], "7997.0");            // the inside of the bend
  EXPECT_EQ(rows[5][0], "S-" + straight + "-R1-C1");  // the straight leg, flat
  EXPECT_EQ(rows[5][blank + 3], "");
}

}  // namespace
}  // namespace curdle
