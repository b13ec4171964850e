// Tests of sheet_drawing.h: the view places layout millimetres on paper at the scale, y down,
// and lines too wide for their room are cut short.
#include "export/sheet_drawing.h"

#include <cairo.h>
#include <gtest/gtest.h>

namespace curdle::sheet_drawing {
namespace {

TEST(SheetDrawing, ViewsAndTextFitTheSheet) {
  View v;
  v.window = Rect{1000, 500, 2000, 1000};
  v.scale = 20;
  v.left = 10, v.top = 15;
  EXPECT_DOUBLE_EQ(v.x(1000), 10);
  EXPECT_DOUBLE_EQ(v.x(3000), 110);
  EXPECT_DOUBLE_EQ(v.y(1500), 15);  // the window's top on the sheet's top
  EXPECT_DOUBLE_EQ(v.y(500), 65);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 100, 100);
  cairo_t* cr = cairo_create(surface);
  const double wide = text_width(cr, "installer's sheet 12 of 40", 2.5);
  EXPECT_GT(wide, text_width(cr, "sheet", 2.5));
  // Twice the height, about twice the width (the font's hinting rounds).
  EXPECT_NEAR(text_width(cr, "sheet", 5) / text_width(cr, "sheet", 2.5), 2, 0.15);
  const auto lines = fit_lines(cr, {"installer's sheet 12 of 40", "ok"}, wide / 2, 2.5);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("..."), std::string::npos);
  EXPECT_LE(text_width(cr, lines[0], 2.5), wide / 2 + 1e-9);
  EXPECT_EQ(lines[1], "ok");
  // Wrapped at spaces where there is room for more lines, not cut: every word is kept.
  const std::string long_line =
      "Square in three granites from two overlaid curds with the same shares";
  const auto wrapped = wrap_lines(cr, {long_line, "ok"}, wide, 2.5, 6);
  ASSERT_GT(wrapped.size(), 2u);
  std::string joined;
  for (size_t i = 0; i + 1 < wrapped.size(); ++i) {
    EXPECT_LE(text_width(cr, wrapped[i], 2.5), wide + 1e-9) << wrapped[i];
    EXPECT_EQ(wrapped[i].find("..."), std::string::npos);
    joined += (i ? " " : "") + wrapped[i];
  }
  EXPECT_EQ(joined, long_line);
  EXPECT_EQ(wrapped.back(), "ok");
  // With no room for more lines, the rest is cut as before.
  const auto tight = wrap_lines(cr, {long_line, "ok"}, wide, 2.5, 2);
  ASSERT_EQ(tight.size(), 2u);
  EXPECT_NE(tight[0].find("..."), std::string::npos);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}

// An ID on its piece stands on a white halo, so that a zone's outline or a joint under it does
// not strike it through: drawn over a dark line, the line is broken round the letters.
TEST(SheetDrawing, TextOnAHaloBreaksTheLineUnderIt) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 200, 60);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);  // a mid-grey piece
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);  // a dark dashed zone line through the text
  cairo_set_line_width(cr, 2);
  cairo_move_to(cr, 0, 27);
  cairo_line_to(cr, 200, 27);
  cairo_stroke(cr);
  text_on_halo(cr, 100, 33, "P-R10-C11", 16, Align::centre);
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  int white = 0;
  for (int x = 30; x < 170; ++x) {
    const unsigned char* p = data + 27 * stride + 4 * x;
    white += p[0] > 200 && p[1] > 200 && p[2] > 200;
  }
  EXPECT_GT(white, 10);  // the line is broken by the halo along the text
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}

}  // namespace
}  // namespace curdle::sheet_drawing
