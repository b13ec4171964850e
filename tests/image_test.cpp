// Tests of image.h: a PNG curdle encodes reads back through OpenImageIO with its size and its
// luminance, top row first.
#include "io/image.h"

#include <gtest/gtest.h>

#include "picture_support.h"

namespace curdle {
namespace {

TEST(Image, APngReadsBackWithItsSizeAndLuminance) {
  const auto dir = test::scratch("image");
  const auto path = test::write_file(
      dir / "ramp.png", test::grey_png(5, 3, [](int x, int y) { return y == 0 ? 0 : x * 60; }));
  const ImageSize size = read_image_size(path, "png");
  EXPECT_EQ(size.width, 5);
  EXPECT_EQ(size.height, 3);
  const LuminanceImage image = read_luminance(path, "png");
  ASSERT_EQ(image.luminance.size(), 15u);
  EXPECT_NEAR(image.luminance[0 * 5 + 4], 0, 1e-6);                   // the top row is black
  EXPECT_LT(image.luminance[2 * 5 + 1], image.luminance[2 * 5 + 4]);  // brighter to the right
  EXPECT_NEAR(image.luminance[2 * 5 + 0], 0, 1e-6);
  EXPECT_THROW(read_luminance(dir / "missing.png", "png"), std::runtime_error);
  std::filesystem::remove_all(dir);
}

// Decoded by what the bytes are: a PNG under the name of a camera's raw file, a DICOM scan or
// an RLA image reads as the PNG it is.
TEST(Image, APictureIsDecodedByItsFormatNotItsName) {
  const auto dir = test::scratch("image-names");
  for (const char* name : {"picture.dng", "picture.dcm", "picture.rla", "picture.cr2"}) {
    const auto path =
        test::write_file(dir / name, test::grey_png(4, 2, [](int x, int) { return x * 80; }));
    EXPECT_EQ(read_luminance(path, "png").width, 4) << name;
    EXPECT_EQ(read_image_size(path, "png").height, 2) << name;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curdle
