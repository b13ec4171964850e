// Tests of wkt.h: lengths to the micrometre, and outlines as WKT polygons that close.
#include "layout/wkt.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(Wkt, LengthsAndPolygons) {
  EXPECT_EQ(mm_text(1.23456), "1.235");
  EXPECT_EQ(mm_text(300), "300");
  EXPECT_EQ(mm_text(-0.0001), "0");  // never "-0"
  EXPECT_EQ(outlines_wkt({}), "");
  const Outline square{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, 100};
  const std::string one = outlines_wkt({square});
  EXPECT_EQ(one.rfind("POLYGON ((0 0, 10 0, 10 10, 0 10", 0), 0u) << one;
  EXPECT_NE(one.find("0 0))"), std::string::npos) << one;  // the ring closes on its start
  const std::string two = outlines_wkt({square, square});
  EXPECT_EQ(two.rfind("MULTIPOLYGON (((", 0), 0u) << two;
  // Appended in place, the same text after what a row already holds.
  std::string row = "x,";
  append_mm_text(row, 12.5004);
  row += ',';
  append_outlines_wkt(row, {square, square});
  EXPECT_EQ(row, "x,12.5," + two);
  EXPECT_EQ(mm_text(0.1), "0.1");
  EXPECT_EQ(mm_text(-2.0005), "-2.001");  // halves away from zero, as std::round
}

}  // namespace
}  // namespace curdle
