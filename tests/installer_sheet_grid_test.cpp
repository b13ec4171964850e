// Tests of installer_sheet_grid.h: the sheets cover the layout and its band of paper without
// gaps, neighbours carry match captions, and a named scale's set is bounded.
#include "layout/installer_sheet_grid.h"

#include <gtest/gtest.h>

#include "building_support.h"
#include "curdle/error.h"
#include "layout_support.h"

namespace curdle {
namespace {

Layout paving(double width, double height) {
  LayoutSpec spec = test::layout_spec("paving");
  spec.module_w = 600, spec.module_h = 300, spec.joint = 0;
  spec.size = std::array<double, 2>{width, height};
  return lay_floor(test::design(2, 2, {{"1/2", "1/2"}}), spec, 5);
}

TEST(InstallerSheetGrid, SheetsTileTheLayoutAndNeighboursNameEachOther) {
  const Layout layout = paving(18000, 12000);
  InstallerPlan plan;
  plan.paper = *paper_sheet("A3");
  plan.viewport = installer_viewport(plan.paper, true);
  lay_sheets(installer_pieces(layout), 50, layout, plan);
  EXPECT_EQ(plan.scale, 50);
  ASSERT_EQ(plan.sheets.size(), plan.grid_rows * plan.grid_columns);
  ASSERT_GT(plan.sheets.size(), 1u);
  // Edge to edge, no sheet wider than its viewport, the layout inside the grid.
  EXPECT_LE(plan.column_edges.front(), 0);
  EXPECT_GE(plan.column_edges.back(), layout.width);
  EXPECT_LE(plan.row_edges.front(), 0);
  EXPECT_GE(plan.row_edges.back(), layout.height);
  for (const InstallerSheet& s : plan.sheets) {
    EXPECT_LE(s.window.w, plan.viewport[0] * 50 + 1e-6);
    EXPECT_LE(s.window.h, plan.viewport[1] * 50 + 1e-6);
    EXPECT_EQ(sheet_holding(plan, s.window.x + s.window.w / 2, s.window.y + s.window.h / 2),
              s.row * plan.grid_columns + s.column);
  }
  // Every shared edge is captioned from both sides.
  size_t shared =
      plan.grid_rows * (plan.grid_columns - 1) + plan.grid_columns * (plan.grid_rows - 1);
  EXPECT_EQ(plan.captions.size(), 2 * shared);
}

TEST(InstallerSheetGrid, ANamedScaleOfTooManySheetsIsRefusedWithOneThatFits) {
  const Layout layout = paving(20000, 20000);
  InstallerPlan plan;
  plan.paper = *paper_sheet("A4");
  plan.viewport = installer_viewport(plan.paper, true);
  try {
    check_named_scale(layout, plan, 1);
    FAIL() << "1 : 1 on A4 over 20 m was taken";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("installer's sheets; at most 500"), std::string::npos) << message;
    EXPECT_NE(message.find("(1 : 5 or beyond)"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(check_named_scale(layout, plan, 5));  // about 486 sheets
}

// Sheets are balanced by what they hold: a joint running straight across near where a sheet
// must end no longer draws the edge there, leaving the next sheet a sliver (the herringbone
// driveway's second row held its curved edge's tip, half the A3 empty).
TEST(InstallerSheetGrid, SheetsAreBalancedByWhatTheyHold) {
  const double scale = 20;
  InstallerPlan plan;
  plan.paper = *paper_sheet("A3");
  plan.viewport = installer_viewport(plan.paper, true, true);
  const double sheet = plan.viewport[1] * scale;  // a sheet's height on the ground
  const Layout layout = paving(2400, 1.2 * sheet);
  // Courses of 150 mm units in columns staggered by half a unit, so that only one line
  // crosses no unit: where every column stops, just below the first sheet's reach.
  const double straight = std::floor((sheet - 16 * scale) / 150 - 1) * 150;
  std::vector<InstallerPiece> pieces;
  for (int c = 0; c < 8; ++c)
    for (double y = c % 2 ? -75 : 0; y < layout.height; y += 150) {
      const double y0 = y < straight && y + 150 > straight ? straight : std::max(0.0, y);
      const double y1 =
          y < straight && y + 150 > straight ? y + 150 : std::min(y + 150, layout.height);
      for (const auto& [a, b] : {std::pair{std::max(0.0, y), std::min(y0, y1)}, std::pair{y0, y1}})
        if (b > a + 1e-9) {
          const Rect r{c * 300.0, a, 300, b - a};
          std::string id = "P";  // appended: GCC 12 warns falsely on "P" + std::string
          id += std::to_string(pieces.size());
          pieces.push_back({id, {r}, r});
        }
    }
  lay_sheets(pieces, scale, layout, plan);
  ASSERT_EQ(plan.grid_rows, 2u);
  std::vector<size_t> held(2, 0);
  for (const InstallerPiece& p : pieces)
    ++held[sheet_holding(plan, p.bounds.x + p.bounds.w / 2, p.bounds.y + p.bounds.h / 2)];
  for (const size_t h : held)
    EXPECT_GE(static_cast<double>(h), 0.4 * static_cast<double>(pieces.size()))
        << held[0] << " and " << held[1] << " pieces";
}

TEST(InstallerSheetGrid, ABuildingsSheetsEachHoldOneFacadeWithTheCornersOnTheirEdges) {
  const Layout l = test::lay_recipe(test::pavilion_recipe());
  const InstallerPlan plan = plan_installer_sheets(l);
  ASSERT_GT(plan.grid_columns, l.frames().size() - 1);
  for (const InstallerSheet& sheet : plan.sheets)
    for (const SurfaceFrame& f : l.frames()) {
      const double corner = f.start + f.length;
      if (&f == &l.frames().back()) continue;  // the strip's end: the band of paper beyond it
      EXPECT_FALSE(corner > sheet.window.x + 1e-6 && corner < sheet.window.right() - 1e-6)
          << "the corner at " << corner << " mm crosses a sheet from " << sheet.window.x;
    }
}

}  // namespace
}  // namespace curdle
