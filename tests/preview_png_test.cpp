// Tests of preview_png.h.
#include "export/report/preview_png.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <memory>

#include "export_support.h"

namespace fs = std::filesystem;

namespace curdle {
using test::design;

namespace {

// A PNG as libpng reads it, independently of curdle's own reader: its pixels as 8-bit RGB and
// its resolution in pixels an inch (0 without a pHYs chunk in metres).
struct ReadBack {
  int width = 0, height = 0, channels = 0;
  double dpi = 0;
  std::vector<uint8_t> rgb;
};

ReadBack read_with_libpng(const fs::path& path) {
  ReadBack r;
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!file) return r;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return ReadBack{};
  }
  png_init_io(png, file.get());
  png_read_info(png, info);
  r.width = static_cast<int>(png_get_image_width(png, info));
  r.height = static_cast<int>(png_get_image_height(png, info));
  r.channels = png_get_channels(png, info);
  png_uint_32 x = 0, y = 0;
  int unit = 0;
  if (png_get_pHYs(png, info, &x, &y, &unit) && unit == PNG_RESOLUTION_METER) r.dpi = x * 0.0254;
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_strip_alpha(png);
  png_read_update_info(png, info);
  r.rgb.resize(static_cast<size_t>(r.width) * r.height * 3);
  for (int row = 0; row < r.height; ++row)
    png_read_row(png, &r.rgb[static_cast<size_t>(row) * r.width * 3], nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return r;
}

}  // namespace

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
  const ReadBack back = read_with_libpng(dir / "p.png");
  EXPECT_EQ(back.width, img.width);
  EXPECT_EQ(back.channels, 3);
  EXPECT_NEAR(back.dpi, 300, 0.02);  // pixels a metre, whole: 11,811
  EXPECT_EQ(back.rgb, img.rgb);
  const LuminanceImage grey = read_luminance(dir / "p.png", "png");
  ASSERT_EQ(grey.width, img.width);
  EXPECT_NEAR(grey.luminance[0],
              (0.2126f * img.rgb[0] + 0.7152f * img.rgb[1] + 0.0722f * img.rgb[2]) / 255, 1e-3);
  EXPECT_THROW(read_luminance(dir / "missing.png", "png"), std::runtime_error);
  fs::remove_all(dir);
}

}  // namespace curdle
