// Tests of course_marks.h: a coursed sheet carries its gauge rod beside the window, the storey
// levels across it, and its chain of dimensions under the column numbers, in ink that a
// printer puts on paper.
#include "export/drawing/course_marks.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle::sheet_drawing {
namespace {

constexpr double kPxPerMm = 4;

// Whether any pixel of the row or column between a and b (paper mm) is not white.
bool inked(cairo_surface_t* s, bool row, double at, double a, double b) {
  cairo_surface_flush(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int k = static_cast<int>(a * kPxPerMm); k <= static_cast<int>(b * kPxPerMm); ++k) {
    const int x = row ? k : static_cast<int>(at * kPxPerMm);
    const int y = row ? static_cast<int>(at * kPxPerMm) : k;
    const uint32_t px = *reinterpret_cast<const uint32_t*>(data + y * stride + x * 4);
    if ((px & 0xffffff) != 0xffffff) return true;
  }
  return false;
}

TEST(CourseMarks, TheGaugeRodTheLevelsAndTheChainAreDrawn) {
  LayoutSpec spec = test::layout_spec("paving");
  spec.module_w = 215, spec.module_h = 65, spec.joint = 10;
  spec.size = std::array<double, 2>{2000, 1500};
  Layout layout = lay_floor(test::design(2, 2, {{"1/2", "1/2"}}), spec, 3);
  layout.drawing.storey = 750;
  const LayingExtents extents = laying_extents(layout);
  View v;
  v.window = Rect{0, 0, 2000, 1500};
  v.scale = 20;
  v.left = 10, v.top = 10;
  const std::array<double, 2> viewport{120, 90};  // the window is 100 x 75 mm of it
  cairo_surface_t* s = cairo_image_surface_create(
      CAIRO_FORMAT_RGB24, static_cast<int>(180 * kPxPerMm), static_cast<int>(140 * kPxPerMm));
  cairo_t* cr = cairo_create(s);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_scale(cr, kPxPerMm, kPxPerMm);
  draw_gauge_rod(cr, layout, extents, v, viewport);
  // The rod 6 mm right of the wall's edge (x 110), from its foot to its top; the level at
  // 750 mm dashed across the wall; nothing else drawn on it.
  EXPECT_TRUE(inked(s, false, 116, v.y(1400), v.y(100)));
  EXPECT_TRUE(inked(s, true, v.y(750), 11, 100));
  EXPECT_FALSE(inked(s, true, v.y(600) - 0.5, 11, 100));
  EXPECT_FALSE(inked(s, false, 50, 11, 80));
  draw_dimension_chain(cr, layout, v, viewport);
  EXPECT_TRUE(inked(s, true, 10 + 90 + 13, 12, 108));  // under the column numbers
  cairo_destroy(cr);
  cairo_surface_destroy(s);
}

}  // namespace
}  // namespace curdle::sheet_drawing
