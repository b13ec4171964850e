// Tests of png_reader.h: every kind of PNG read in process gives, value for value, what the
// OpenImageIO module gives for the same file; a broken file is refused with libpng's reason.
#include "io/png_reader.h"

#include <dlfcn.h>
#include <gtest/gtest.h>
#include <png.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "io/module_loader.h"

namespace curdle {
namespace {

struct Png {
  int colour_type = PNG_COLOR_TYPE_RGB;
  int depth = 8;
  bool interlaced = false;
  bool transparent = false;  // a palette with a tRNS chunk
};

// A w x h picture of that kind, its samples running through their whole range.
std::string write_png(const Png& kind, int w, int h) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_set_write_fn(
      png, &out,
      [](png_structp p, png_bytep data, png_size_t n) {
        static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<char*>(data), n);
      },
      nullptr);
  png_set_IHDR(png, info, w, h, kind.depth, kind.colour_type,
               kind.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  std::vector<png_color> palette;
  std::vector<png_byte> alpha;
  if (kind.colour_type == PNG_COLOR_TYPE_PALETTE) {
    for (int i = 0; i < (1 << kind.depth); ++i) {
      palette.push_back({static_cast<png_byte>(i * 37), static_cast<png_byte>(255 - i * 11),
                         static_cast<png_byte>(i * 5)});
      alpha.push_back(static_cast<png_byte>(255 - i * 3));
    }
    png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    if (kind.transparent)
      png_set_tRNS(png, info, alpha.data(), static_cast<int>(alpha.size()), nullptr);
  }
  png_write_info(png, info);
  const int samples = png_get_channels(png, info);
  const size_t stride = (static_cast<size_t>(w) * samples * kind.depth + 7) / 8;
  std::vector<png_byte> rows(stride * h);
  for (size_t i = 0; i < rows.size(); ++i)
    rows[i] = static_cast<png_byte>(i * 7919 + i / stride * 31);
  if (kind.colour_type == PNG_COLOR_TYPE_PALETTE && kind.depth == 8)
    for (auto& b : rows) b = static_cast<png_byte>(b % palette.size());
  std::vector<png_bytep> pointers;
  for (int y = 0; y < h; ++y) pointers.push_back(rows.data() + y * stride);
  png_write_image(png, pointers.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

// The same file read by the OpenImageIO module.
LuminanceImage through_module(const std::string& bytes) {
  const std::string path = testing::TempDir() + "/png_reader_test.png";
  std::ofstream(path, std::ios::binary) << bytes;
  std::string failure;
  void* handle = load_curdle_module(CURDLE_IMAGE_MODULE_NAME_FOR_TESTS, &failure);
  EXPECT_NE(handle, nullptr) << failure;
  auto read = reinterpret_cast<ReadLuminanceFn>(::dlsym(handle, "curdle_image_read_luminance_as"));
  LuminanceImage image;
  std::string error;
  EXPECT_TRUE(read(path.c_str(), "png", &image, &error)) << error;
  return image;
}

void expect_same(const LuminanceImage& ours, const LuminanceImage& theirs,
                 const std::string& what) {
  ASSERT_EQ(ours.width, theirs.width) << what;
  ASSERT_EQ(ours.height, theirs.height) << what;
  ASSERT_EQ(ours.luminance.size(), theirs.luminance.size()) << what;
  for (size_t i = 0; i < ours.luminance.size(); ++i)
    ASSERT_EQ(ours.luminance[i], theirs.luminance[i]) << what << ", pixel " << i;
  EXPECT_EQ(ours.colour, theirs.colour) << what;
  EXPECT_EQ(ours.palette, theirs.palette) << what;
}

TEST(PngReader, EveryKindOfPngReadsAsOpenImageIOReadsIt) {
  const std::vector<std::pair<std::string, Png>> kinds{
      {"grey 1 bit", {PNG_COLOR_TYPE_GRAY, 1}},
      {"grey 4 bits", {PNG_COLOR_TYPE_GRAY, 4}},
      {"grey 8 bits", {PNG_COLOR_TYPE_GRAY, 8}},
      {"grey 16 bits", {PNG_COLOR_TYPE_GRAY, 16}},
      {"grey and alpha", {PNG_COLOR_TYPE_GRAY_ALPHA, 8}},
      {"RGB", {PNG_COLOR_TYPE_RGB, 8}},
      {"RGB interlaced", {PNG_COLOR_TYPE_RGB, 8, true}},
      {"RGB 16 bits", {PNG_COLOR_TYPE_RGB, 16}},
      {"RGBA", {PNG_COLOR_TYPE_RGB_ALPHA, 8}},
      {"palette of 4", {PNG_COLOR_TYPE_PALETTE, 2}},
      {"palette of 256", {PNG_COLOR_TYPE_PALETTE, 8}},
      {"palette with transparency", {PNG_COLOR_TYPE_PALETTE, 8, false, true}},
  };
  for (const auto& [what, kind] : kinds) {
    const std::string bytes = write_png(kind, 37, 23);
    const LuminanceImage ours = read_png_luminance(bytes);
    expect_same(ours, through_module(bytes), what);
    const ImageSize size = read_png_size(bytes);
    EXPECT_EQ(size.width, 37) << what;
    EXPECT_EQ(size.height, 23) << what;
  }
  // A flat drawing keeps its few colours.
  std::ifstream mask(std::string(CURDLE_SOURCE_DIR) + "/patterns/gallery-facade-mask.png",
                     std::ios::binary);
  std::stringstream shipped;
  shipped << mask.rdbuf();
  const LuminanceImage drawn = read_png_luminance(shipped.str());
  expect_same(drawn, through_module(shipped.str()), "the shipped mask");
  EXPECT_FALSE(drawn.palette.empty());
}

TEST(PngReader, ABrokenPngIsRefusedWithLibpngsReason) {
  const std::string bytes = write_png({PNG_COLOR_TYPE_RGB, 8}, 64, 64);
  try {
    read_png_luminance(bytes.substr(0, bytes.size() / 2));
    ADD_FAILURE() << "half a PNG was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("ends early"), std::string::npos) << e.what();
  }
  std::string corrupt = bytes;
  corrupt[20] ^= 0x55;  // IHDR's CRC no longer matches
  EXPECT_THROW(read_png_size(corrupt), std::runtime_error);
  EXPECT_THROW(read_png_luminance("not a picture"), std::runtime_error);
}

}  // namespace
}  // namespace curdle
