// Tests of layout_png.h.
#include "export/drawing/layout_png.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
using test::design;

TEST(Layout, PngColoursEachElementAndRecordsItsScale) {
  const Design d = design(4, 2, {{"3/4", "2/3"}});
  const CurdField f = curdle(d, 8, d.field);
  LayoutSpec spec = test::layout_spec();
  spec.joint = 20;
  Layout layout = make_layout(d, f, d.field, spec);
  EXPECT_EQ(drawing_scale(layout), 20);                 // 5.1 m fits an A3 sheet at 1:20
  layout.drawing.scale = 10, layout.drawing.dpi = 254;  // 1 px = 1 mm / (254 / 25.4 / 10) = 1 mm
  const PreviewImage png = render_layout(layout);
  EXPECT_EQ(png.width, static_cast<int>(std::ceil(layout.width)));
  for (const Element& e : layout.elements) {
    const size_t px = static_cast<size_t>(e.nominal.x + 150),
                 py = static_cast<size_t>(layout.height - e.nominal.y - 150);
    const uint8_t* p = &png.rgb[(py * png.width + px) * 3];
    EXPECT_EQ((Rgb{p[0], p[1], p[2]}), layout.legend[e.value].colour) << e.id;
  }
}

// Pieces that meet inside a pixel share it with no light seam: each takes its share from the
// ground, where one painted over the other left a quarter of the ground showing (a park's
// cells of one material were ruled by light lines at 200 dpi).
TEST(Layout, PiecesMeetingInsideAPixelLeaveNoSeam) {
  const Design d = design(4, 2, {{"1", "1"}});
  LayoutSpec spec = test::layout_spec();  // no joints: the pieces meet
  spec.combine = Combine::keep;           // on white: the ground differs from every piece
  Layout layout = make_layout(d, curdle(d, 1, d.field), d.field, spec);
  layout.drawing.scale = 10, layout.drawing.dpi = 254 / 7.0;  // 1 px = 7 mm: edges mid-pixel
  const PreviewImage png = render_layout(layout);
  size_t off = 0;
  for (int y = 0; y + 1 < png.height; ++y)  // the last row and column run past the surface
    for (int x = 0; x + 1 < png.width; ++x)
      for (int c = 0; c < 3; ++c)
        off += std::abs(png.rgb[(static_cast<size_t>(y) * png.width + x) * 3 + c] - png.rgb[c]) > 1;
  EXPECT_EQ(off, 0u);  // every pixel the pieces' one colour
}

}  // namespace curdle
