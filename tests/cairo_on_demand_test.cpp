// Tests of cairo_on_demand.h: cairo is there to be loaded, and a drawing made through the
// forwarders is cairo's own (pixels and a PDF stream as cairo makes them).
#include "export/drawing/cairo_on_demand.h"

#include <cairo-pdf.h>
#include <cairo.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace curdle {
namespace {

TEST(CairoOnDemand, IsInstalledWithNoReasonGiven) {
  std::string why = "unchanged";
  EXPECT_TRUE(cairo_installed(&why));
  EXPECT_EQ(why, "unchanged");
}

TEST(CairoOnDemand, AnImageDrawnThroughItHasCairosPixels) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 4, 4);
  ASSERT_EQ(cairo_surface_status(surface), CAIRO_STATUS_SUCCESS)
      << cairo_status_to_string(cairo_surface_status(surface));
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgba(cr, 1, 0, 0, 1);
  cairo_rectangle(cr, 0, 0, 2, 4);  // the left half red, the right half left clear
  cairo_fill(cr);
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  auto pixel = [&](int x, int y) {
    return *reinterpret_cast<const std::uint32_t*>(data + y * stride + x * 4);
  };
  EXPECT_EQ(pixel(0, 0), 0xFFFF0000u);
  EXPECT_EQ(pixel(1, 3), 0xFFFF0000u);
  EXPECT_EQ(pixel(2, 0), 0u);
  EXPECT_EQ(pixel(3, 3), 0u);
  cairo_surface_destroy(surface);
}

TEST(CairoOnDemand, APdfWrittenThroughItIsAPdf) {
  std::string pdf;
  cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(
      [](void* closure, const unsigned char* bytes, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(bytes), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &pdf, 595, 842);
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, "a test sheet");
  cairo_t* cr = cairo_create(surface);
  cairo_move_to(cr, 100, 100);
  cairo_line_to(cr, 200, 200);
  cairo_stroke(cr);
  cairo_show_page(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  EXPECT_EQ(cairo_surface_status(surface), CAIRO_STATUS_SUCCESS);
  cairo_surface_destroy(surface);
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("a test sheet"), std::string::npos);
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
}

}  // namespace
}  // namespace curdle
