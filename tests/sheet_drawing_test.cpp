// Tests of sheet_drawing.h: the view places layout millimetres on paper at the scale, y down,
// and lines too wide for their room are cut short.
#include "export/drawing/sheet_drawing.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "layout_support.h"

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

// A ring's path drops the corners a drawing cannot show: a 32 mm circle polygonised to a
// micrometre is drawn at 1:20 with a fraction of its corners, none further than a hundredth
// of a paper millimetre (and a little, for the corners left out in a row) from the path.
TEST(SheetDrawing, RingsLeaveOutCornersCloserThanAHundredthOfAMillimetreOnPaper) {
  View v;
  v.window = Rect{0, 0, 1000, 1000};
  v.scale = 20;
  Ring ring;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < 400; ++i)
    ring.push_back({500 + 16 * std::cos(2 * pi * i / 400), 500 + 16 * std::sin(2 * pi * i / 400)});
  ring.push_back({560, 500});  // a spike out of the circle is kept whatever its neighbours
  ring.push_back({516, 500});
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 10, 10);
  cairo_t* cr = cairo_create(surface);
  ring_paths(cr, {ring}, v);
  cairo_path_t* path = cairo_copy_path(cr);
  std::vector<std::array<double, 2>> drawn;
  for (int i = 0; i < path->num_data; i += path->data[i].header.length)
    if (path->data[i].header.type != CAIRO_PATH_CLOSE_PATH)
      drawn.push_back({path->data[i + 1].point.x, path->data[i + 1].point.y});
  cairo_path_destroy(path);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  EXPECT_LT(drawn.size(), 60u);
  EXPECT_GT(drawn.size(), 10u);
  bool spike = false;
  for (const auto& p : drawn) spike = spike || std::hypot(p[0] - v.x(560), p[1] - v.y(500)) < 1e-9;
  EXPECT_TRUE(spike);
  // Every corner of the ring lies within 0.02 mm of the drawn path.
  for (const auto& [x, y] : ring) {
    const double px = v.x(x), py = v.y(y);
    double nearest = 1e9;
    for (size_t i = 0; i < drawn.size(); ++i) {
      const auto& a = drawn[i];
      const auto& b = drawn[(i + 1) % drawn.size()];
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      const double t =
          std::clamp(((px - a[0]) * dx + (py - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      nearest = std::min(nearest, std::hypot(a[0] + t * dx - px, a[1] + t * dy - py));
    }
    EXPECT_LT(nearest, 0.02) << x << ", " << y;
  }
}

// Pieces that meet (no joints) are filled one path a colour: filled one by one, a reader that
// smooths each fill's edges left a light seam where two pieces of a material meet.
TEST(SheetDrawing, PiecesThatMeetLeaveNoSeam) {
  const Design d = test::design(4, 2, {{"1", "1"}});
  LayoutSpec spec = test::layout_spec();  // no joints: the pieces meet
  spec.combine = Combine::keep;           // on white: the ground differs from every piece
  const Layout layout = make_layout(d, curdle(d, 1, d.field), d.field, spec);
  View v;
  v.window = Rect{0, 0, layout.width, layout.height};
  v.scale = 7;  // a pixel a paper mm: 7 mm, so that the pieces' edges fall inside pixels
  const int w = static_cast<int>(layout.width / 7), h = static_cast<int>(layout.height / 7);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  cairo_t* cr = cairo_create(surface);
  draw_pieces(cr, layout, v, false);
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  auto channel = [&](int x, int y, int c) { return int{data[y * stride + x * 4 + c]}; };
  size_t off = 0;  // pixels more than a rounding from the first
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) off += std::abs(channel(x, y, c) - channel(0, 0, c)) > 2;
  EXPECT_EQ(off, 0u);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}

}  // namespace
}  // namespace curdle::sheet_drawing
