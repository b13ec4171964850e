// Tests of preview_png.h.
#include "export/report/preview_png.h"

#include <gtest/gtest.h>

#include "export_support.h"

namespace fs = std::filesystem;

namespace curdle {
using test::design;

TEST(Preview, ShowsEachCellInItsValueColourWithYUp) {
  Design d = design(4, 2, {{"3/4", "2/3"}, {"1/2", "1/2"}});
  const CurdField f = curdle(d, 3, d.field);
  const PreviewImage img = render_preview(d, f, d.field);
  ASSERT_EQ(img.width, 512);  // 16 cells x 32 px
  ASSERT_EQ(img.height, 512);
  const auto colours = value_colours(d.curds);
  for (int64_t y : {0, 5, 15})
    for (int64_t x : {0, 7, 15}) {
      const Rgb c = colours[f.value_at({x, y, 0})];
      const size_t px = static_cast<size_t>(x * 32 + 16),
                   py = static_cast<size_t>((15 - y) * 32 + 16);
      const uint8_t* p = &img.rgb[(py * img.width + px) * 3];
      EXPECT_EQ(Rgb({p[0], p[1], p[2]}), c) << x << "," << y;
    }
}

TEST(Preview, StripsAndSheetsAndLargeFields) {
  const Design line =
      design(2, 1, std::vector<std::vector<std::string>>{std::vector<std::string>(12, "3/4")});
  const PreviewImage strip = render_preview(line, curdle(line, 1, line.field), line.field);
  EXPECT_GT(strip.width, strip.height);
  const Design cube = design(4, 3, {{"3/4", "3/4"}});
  const PreviewImage sheet = render_preview(cube, curdle(cube, 1, cube.field), cube.field);
  EXPECT_EQ(sheet.width, sheet.height);  // 16 slices in a 4 x 4 sheet
  // 8192 cells wide, a strip of the lattice: as wide as the whole 2^13 x 2^13 lattice, in a
  // thousandth of the cells (the whole lattice took 2 s).
  Design big =
      design(2, 2, std::vector<std::vector<std::string>>{std::vector<std::string>(13, "3/4")});
  big.field.size = {8192, 64, 1};
  const PreviewImage down = render_preview(big, curdle(big, 1, big.field), big.field);
  EXPECT_LE(down.width, 4096);  // 8192 cells averaged two to a pixel
  EXPECT_EQ(preview_memory(big, big.field), uint64_t(down.width) * down.height * 19);
}

TEST(Preview, EncodesAPngThatReadsBackWithItsResolution) {
  const fs::path dir = temp_dir("png");
  Design d = design(4, 2, {{"3/4", "2/3"}});
  const PreviewImage img = render_preview(d, curdle(d, 3, d.field), d.field);
  write_file(dir / "p.png", [&](std::ostream& o) { o << encode_png(img, 300); });
  auto in = OIIO::ImageInput::open((dir / "p.png").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, img.width);
  EXPECT_EQ(in->spec().nchannels, 3);
  EXPECT_NEAR(in->spec().get_float_attribute("XResolution"), 300, 1e-3);
  std::vector<uint8_t> back(img.rgb.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, back.data()));
  EXPECT_EQ(back, img.rgb);
  const LuminanceImage grey = read_luminance(dir / "p.png", "png");
  ASSERT_EQ(grey.width, img.width);
  EXPECT_NEAR(grey.luminance[0],
              (0.2126f * img.rgb[0] + 0.7152f * img.rgb[1] + 0.0722f * img.rgb[2]) / 255, 1e-3);
  EXPECT_THROW(read_luminance(dir / "missing.png", "png"), std::runtime_error);
  fs::remove_all(dir);
}

}  // namespace curdle
