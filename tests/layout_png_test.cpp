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

}  // namespace curdle
