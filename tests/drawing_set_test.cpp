// Tests of drawing_set.h: layout.pdf holds sheet 1 and every installer's sheet; the overview's
// sheet holds the drawing at its scale.
#include "export/drawing/drawing_set.h"

#include <gtest/gtest.h>

#include <sstream>

#include "layout/installer_sheets.h"
#include "layout_support.h"

namespace curdle {
namespace {

TEST(DrawingSet, ThePdfHoldsSheetOneAndEveryInstallersSheet) {
  const Design d = test::design(2, 2, {{"3/4", "2/3", "2/3"}});
  LayoutSpec spec = test::layout_spec("paving");
  spec.size = std::array<double, 2>{4800, 2400};
  spec.module_w = spec.module_h = 300;
  const Layout layout = lay_floor(d, spec, 6);
  const InstallerPlan plan = plan_installer_sheets(layout);
  std::ostringstream out;
  write_layout_pdf(out, layout, plan);
  const std::string pdf = out.str();
  ASSERT_EQ(pdf.rfind("%PDF-", 0), 0u);
  // Each page object is "/Type /Page" followed by anything but the "s" of "/Pages".
  size_t pages = 0;
  for (size_t at = pdf.find("/Type /Page"); at != std::string::npos;
       at = pdf.find("/Type /Page", at + 1))
    pages += pdf[at + 11] != 's';
  EXPECT_EQ(pages, 1 + plan.sheets.size());
  const OverviewSheet sheet = overview_sheet(layout);
  EXPECT_EQ(sheet.paper.name, "A3");
  EXPECT_TRUE(sheet.landscape);
  EXPECT_LE(4800 / sheet.scale, sheet.paper.long_side);  // the drawing fits the sheet
}

}  // namespace
}  // namespace curdle
