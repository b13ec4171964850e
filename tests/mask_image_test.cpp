// Tests of mask_image.h: a mask's dark pixels become openings stretched over the wall.
#include "site/mask_image.h"

#include <gtest/gtest.h>

#include "curdle/error.h"
#include "picture_support.h"

namespace curdle {
namespace {

TEST(MaskImage, DarkPixelsAreOpeningsOverTheWall) {
  const auto dir = test::scratch("mask");
  // 4 x 2 pixels: a dark square in the top-right quarter.
  const auto mask = test::write_file(dir / "mask.png", test::grey_png(4, 2, [](int x, int y) {
                                       return x >= 2 && y == 0 ? 0 : 255;
                                     }));
  const std::vector<Rect> openings = read_mask_openings(
      mask, 4000, 2000, SourceLocation{"r.toml", 1, 1, "layout.mask", ""}, 1 << 20);
  double area = 0, x0 = 1e9, y0 = 1e9;
  for (const Rect& r : openings) area += r.area(), x0 = std::min(x0, r.x), y0 = std::min(y0, r.y);
  EXPECT_NEAR(area, 2000.0 * 1000, 1e-6);  // a quarter of the wall
  EXPECT_NEAR(x0, 2000, 1e-6);
  EXPECT_NEAR(y0, 1000, 1e-6);  // the picture's top row is the wall's top
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curdle
