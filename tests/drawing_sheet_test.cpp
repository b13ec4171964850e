// Drawings on ISO sheets: standard scales only, the largest drawing that fits the sheet's
// drawing area in either orientation.
#include "layout/drawing_sheet.h"

#include <gtest/gtest.h>

#include <set>

namespace curdle {

TEST(DrawingSheet, TheLargestStandardScaleThatFitsEitherOrientation) {
  const PaperSheet a3 = *paper_sheet("A3");
  // A3 landscape leaves 390 x 227 mm: a 20 m paving at 1 : 100 is 200 x 200 mm.
  EXPECT_EQ(fit_to_sheet(20000, 20000, a3).scale, 100);
  // The brick façade, 18 x 15.6 m: 1 : 50 would be 312 mm high.
  EXPECT_EQ(fit_to_sheet(18000, 15600, a3).scale, 100);
  // Tall and narrow: portrait (267 x 350 mm) takes 1 : 20 where landscape would need 1 : 50.
  const SheetFit tall = fit_to_sheet(4000, 6000, a3);
  EXPECT_EQ(tall.scale, 20);
  EXPECT_FALSE(tall.landscape);
  EXPECT_EQ(fit_to_sheet(300, 200, a3).scale, 1);
  EXPECT_EQ(fit_to_sheet(20000, 20000, *paper_sheet("A1")).scale, 50);
  const std::set<double> standard{1,   2,    5,    10,   20,   25,    50,    100,   200,  250,
                                  500, 1000, 2000, 2500, 5000, 10000, 20000, 25000, 50000};
  for (double size = 100; size < 1e7; size *= 1.37) {
    const SheetFit fit = fit_to_sheet(size, size / 2, a3);
    EXPECT_TRUE(standard.count(fit.scale)) << size << " mm at 1 : " << fit.scale;
    const auto area = drawing_area(a3, fit.landscape);
    EXPECT_LE(size / fit.scale, area[0] + 1e-9);
    EXPECT_LE(size / 2 / fit.scale, area[1] + 1e-9);
  }
  EXPECT_FALSE(paper_sheet("A5"));
  EXPECT_FALSE(paper_sheet("letter"));
}

// Millimetres to a thousandth, rounded as printf's "%.3f" rounds the double itself, with no
// trailing zeros, no lone point and no negative zero.
TEST(DrawingSheet, MillimetresAreWrittenToAThousandth) {
  EXPECT_EQ(drawing_mm(1234.5678), "1234.568");
  EXPECT_EQ(drawing_mm(2.5), "2.5");
  EXPECT_EQ(drawing_mm(600), "600");
  EXPECT_EQ(drawing_mm(1.0005), "1");  // 1.000499999... as a double
  EXPECT_EQ(drawing_mm(-0.0004), "0");
  EXPECT_EQ(drawing_mm(-12.25), "-12.25");
  EXPECT_EQ(drawing_mm(1e12), "1000000000000");
}

}  // namespace curdle
