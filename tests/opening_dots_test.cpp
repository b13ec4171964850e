// Tests of opening_dots.h: a perforated sheet's round and merged openings, drawn as dots, cover
// exactly their circles on paper, faint or not.
#include "export/drawing/opening_dots.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>
#include <utility>

#include "layout/union.h"
#include "layout_support.h"

namespace curdle::sheet_drawing {
namespace {

// Three overlapping holes (16, 12 and 16 mm) a 40 mm cell, kept as their union where they overlap.
Layout perforated_sheet() {
  const Design d = test::design(4, 2, {{"1/2", "1/2"}, {"1/2", "1/2"}, {"1/2", "1/2"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("perforation"));
  spec.combine = Combine::keep;
  spec.module_w = spec.module_h = 40;
  spec.size = std::array<double, 2>{640, 640};
  auto& keys = spec.own<PerforationKeys>();
  keys.thickness = 2;
  keys.holes = {{16, -7, 6}, {12, 5, 6}, {16, 0, -7}};  // two widths: two strokes
  keys.min_diameter = 5;
  keys.edge_margin = 5;
  keys.chord_tolerance = 0.01;
  return make_layout(d, curdle(d, 3, d.field), d.field, spec);
}

struct Picture {
  cairo_surface_t* surface;
  int size;
  const uint8_t* pixel(int x, int y) const {
    return cairo_image_surface_get_data(surface) + y * cairo_image_surface_get_stride(surface) +
           4 * x;
  }
};

constexpr double kPixelsPerMm = 5;

// The layout's window of 200 x 200 mm at 1 : 1, five pixels a millimetre.
Picture draw(const Layout& layout, const View& v, bool faint) {
  const int size = static_cast<int>(v.window.w * kPixelsPerMm);
  Picture p{cairo_image_surface_create(CAIRO_FORMAT_RGB24, size, size), size};
  cairo_t* cr = cairo_create(p.surface);
  cairo_scale(cr, kPixelsPerMm, kPixelsPerMm);
  draw_pieces(cr, layout, v, faint);
  cairo_destroy(cr);
  cairo_surface_flush(p.surface);
  return p;
}

struct Dot {
  Circle circle;  // on paper, mm
  Rgb colour;
};

// The dots by the 40 mm cell they lie in on paper: every hole of a cell lies within 15 mm of
// its centre, so a point's nearest edge within reach is one of its own cell's.
using DotsByCell = std::map<std::pair<int, int>, std::vector<Dot>>;
std::pair<int, int> cell_of(double x, double y) {
  return {static_cast<int>(std::floor(x / 40)), static_cast<int>(std::floor(y / 40))};
}

// How far (mm, negative inside) a point on paper lies from the nearest edge of an opening of its
// cell, and that opening.
std::pair<double, const Dot*> nearest_edge(const DotsByCell& dots, double x, double y) {
  std::pair<double, const Dot*> best{1e9, nullptr};
  const auto cell = dots.find(cell_of(x, y));
  if (cell == dots.end()) return best;
  for (const Dot& d : cell->second) {
    const double edge = std::hypot(x - d.circle.cx, y - d.circle.cy) - d.circle.d / 2;
    if (edge < best.first) best = {edge, &d};
  }
  return best;
}

uint32_t bgr(const uint8_t* px) { return uint32_t{px[2]} << 16 | uint32_t{px[1]} << 8 | px[0]; }
uint32_t rgb(const Rgb& c) { return uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b; }
// Equal to within cairo's rounding of a colour to its pixels: one in each channel.
bool same_colour(uint32_t a, uint32_t b) {
  for (int k = 0; k < 24; k += 8)
    if (std::abs(static_cast<int>(a >> k & 255) - static_cast<int>(b >> k & 255)) > 1) return false;
  return true;
}

}  // namespace

TEST(OpeningDots, AMergedOpeningKeepsTheCirclesItIsTheUnionOf) {
  const Layout layout = perforated_sheet();
  int merged = 0;
  for (const Element& e : layout.elements) {
    EXPECT_TRUE(OpeningDots::takes(e)) << e.id;
    if (!e.outline) continue;
    ++merged;
    ASSERT_EQ(e.outline->circles.size(), static_cast<size_t>(std::popcount(e.value))) << e.id;
    EXPECT_NEAR(union_of_circles(e.outline->circles, 0.01).front().area, e.outline->area, 1e-6);
  }
  EXPECT_GT(merged, 10);
}

// Every pixel further than its own width (0.2 mm) from an opening's edge is the opening's
// colour inside and the bare sheet's outside; faint, every pixel inside is one colour, the
// overlaps of a merged opening's circles included.
TEST(OpeningDots, TheDotsCoverTheOpeningsCirclesAndNothingElse) {
  const Layout layout = perforated_sheet();
  View v;
  v.window = Rect{200, 200, 200, 200};
  v.scale = 1;
  std::vector<Dot> dots;
  for (const Element& e : layout.elements) {
    const Rgb& c = layout.legend[e.value].colour;
    if (e.circle) dots.push_back({*e.circle, c});
    if (e.outline)
      for (const Circle& circle : e.outline->circles) dots.push_back({circle, c});
  }
  DotsByCell by_cell;
  for (Dot d : dots) {
    d.circle.cx = v.x(d.circle.cx), d.circle.cy = v.y(d.circle.cy);
    by_cell[cell_of(d.circle.cx, d.circle.cy)].push_back(d);
  }
  const Rgb metal{201, 205, 210};
  for (const bool faint : {false, true}) {
    const Picture p = draw(layout, v, faint);
    std::map<uint32_t, uint32_t> faint_colour;  // each opening colour's, washed out
    int inside = 0, outside = 0;
    for (int y = 0; y < p.size; ++y)
      for (int x = 0; x < p.size; ++x) {
        const auto [edge, dot] =
            nearest_edge(by_cell, (x + 0.5) / kPixelsPerMm, (y + 0.5) / kPixelsPerMm);
        if (std::abs(edge) < 0.2) continue;  // a pixel (0.2 mm) the edge may cross
        const uint32_t drawn = bgr(p.pixel(x, y));
        if (edge > 0) {
          ++outside;
          if (!faint) {
            ASSERT_TRUE(same_colour(drawn, rgb(metal)))
                << std::hex << drawn << " at " << std::dec << x << "," << y;
          }
          continue;
        }
        ++inside;
        if (!faint) {
          ASSERT_TRUE(same_colour(drawn, rgb(dot->colour)))
              << std::hex << drawn << " at " << std::dec << x << "," << y;
        }
        const uint32_t first = faint_colour.emplace(rgb(dot->colour), drawn).first->second;
        ASSERT_TRUE(same_colour(drawn, first))
            << std::hex << drawn << " at " << std::dec << x << "," << y;
      }
    EXPECT_GT(inside, p.size * p.size / 20);
    EXPECT_GT(outside, p.size * p.size / 20);
    cairo_surface_destroy(p.surface);
  }
}

}  // namespace curdle::sheet_drawing
