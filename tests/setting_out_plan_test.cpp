// Tests of setting_out_plan.h: a curved wall's setting-out plan is drawn on paper, the arc
// inked where it lies in the box; a building with no curved façade, or a box too small to hold
// a plan, draws nothing.
#include "export/drawing/setting_out_plan.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include "building_support.h"

namespace curdle::sheet_drawing {
namespace {

constexpr double kPxPerMm = 4;

// How many pixels of the surface are not white.
size_t inked(cairo_surface_t* s) {
  cairo_surface_flush(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  size_t n = 0;
  for (int y = 0; y < cairo_image_surface_get_height(s); ++y)
    for (int x = 0; x < cairo_image_surface_get_width(s); ++x)
      n += (*reinterpret_cast<const uint32_t*>(data + y * stride + x * 4) & 0xffffff) != 0xffffff;
  return n;
}

size_t drawn(const Layout& l, double w, double h, bool* said) {
  cairo_surface_t* s = cairo_image_surface_create(
      CAIRO_FORMAT_RGB24, static_cast<int>(w * kPxPerMm), static_cast<int>(h * kPxPerMm));
  cairo_t* cr = cairo_create(s);
  cairo_scale(cr, kPxPerMm, kPxPerMm);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  *said = draw_setting_out_plan(cr, l, 0, 0, w, h);
  cairo_destroy(cr);
  const size_t n = inked(s);
  cairo_surface_destroy(s);
  return n;
}

TEST(SettingOutPlan, ACurvedWallIsDrawnAndAStraightOneIsNot) {
  const Layout curved = test::lay_recipe(test::building_recipe(
      "panel = [215, 65]\njoint = 10\n",
      "path = [[0, 0], { centre = [0, 12000], length = 18000 }]\nheight = 600\n"));
  bool said = false;
  EXPECT_GT(drawn(curved, 300, 100, &said), 2000u);
  EXPECT_TRUE(said);
  EXPECT_EQ(drawn(curved, 300, 20, &said), 0u);  // no room for a plan under its lines
  EXPECT_FALSE(said);
  const Layout straight = test::lay_recipe(test::building_recipe(
      "panel = [215, 65]\njoint = 10\n", "path = [[0, 0], [9000, 0]]\nheight = 600\n"));
  EXPECT_EQ(drawn(straight, 300, 100, &said), 0u);
  EXPECT_FALSE(said);
}

}  // namespace
}  // namespace curdle::sheet_drawing
