// Tests of bounded_image.h: a picture a user names is read only when it is a regular file whose
// pixels fit the limits; otherwise the message names it and what is allowed.
#include "io/bounded_image.h"

#include <gtest/gtest.h>

#include "curdle/error.h"
#include "picture_support.h"

namespace curdle {
namespace {

TEST(BoundedImage, ReadsRegularFilesWithinTheLimitsAndRefusesTheRest) {
  const auto dir = test::scratch("bounded");
  const auto png =
      test::write_file(dir / "a.png", test::grey_png(8, 4, [](int x, int) { return x * 30; }));
  const SourceLocation where{"r.toml", 3, 1, "layout.mask", ""};
  const LuminanceImage image = read_bounded_luminance(png, "the mask image", where, 1 << 20);
  EXPECT_EQ(image.width, 8);
  EXPECT_EQ(image.height, 4);
  EXPECT_THROW(read_bounded_luminance(png, "the mask image", where, 1 << 20, 31),
               ResourceLimitError);  // 32 pixels
  EXPECT_THROW(read_bounded_luminance(png, "the mask image", where, 10), ResourceLimitError);
  for (const auto& bad : {dir / "missing.png", dir, std::filesystem::path("/dev/zero")}) {
    try {
      read_bounded_luminance(bad, "the mask image", where, 1 << 20);
      ADD_FAILURE() << bad << " was read";
    } catch (const ResourceLimitError& e) {
      ADD_FAILURE() << bad << ": " << e.what();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("the mask image"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("layout.mask"), std::string::npos) << e.what();
    }
  }
  const auto junk = test::write_file(dir / "junk.png", "not a picture");
  EXPECT_THROW(read_bounded_luminance(junk, "the mask image", where, 1 << 20), InputError);
  // An SGI picture named .png never reaches OpenImageIO's SGI reader, which aborted on it.
  std::string sgi_bytes("\x01\xDA\x01\x01\x00\x03", 6);
  sgi_bytes.append(506, '\xff');  // appended: GCC 12 warns falsely on a sum of two temporaries
  const auto sgi = test::write_file(dir / "sgi.png", sgi_bytes);
  try {
    read_bounded_luminance(sgi, "the picture", where, 1 << 20);
    ADD_FAILURE() << "an SGI picture was decoded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("PNG, JPEG, TIFF or BMP"), std::string::npos) << e.what();
  }
  // A PNG header claiming more pixels than allowed is refused before it is decoded.
  std::string huge = test::grey_png(2, 2, [](int, int) { return 0; });
  huge[16] = '\x7f';  // width 2^30 and more
  const auto big = test::write_file(dir / "big.png", huge);
  EXPECT_THROW(read_bounded_luminance(big, "the picture", where, 1 << 20, 1 << 20),
               ResourceLimitError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curdle
