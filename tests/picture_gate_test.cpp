// Tests of picture_gate.h: the four formats are known by their first bytes and sized by their
// headers, whatever their names; everything else, and every header cut short, is refused before
// a decoder sees it.
#include "export/picture_gate.h"

#include <gtest/gtest.h>

#include <random>

#include "picture_support.h"

namespace curdle {
namespace {

std::string le16(uint32_t v) { return {char(v), char(v >> 8)}; }
std::string le32(uint32_t v) { return le16(v) + le16(v >> 16); }
std::string be16(uint32_t v) { return {char(v >> 8), char(v)}; }
std::string be32(uint32_t v) { return be16(v >> 16) + be16(v); }

std::optional<PictureHeader> header(const std::string& bytes) {
  std::string why;
  return read_picture_header(bytes, why);
}

TEST(PictureGate, TheFourFormatsAreSizedByTheirHeaders) {
  const auto png = header(test::grey_png(7, 3, [](int, int) { return 9; }));
  ASSERT_TRUE(png);
  EXPECT_EQ(png->format, PictureFormat::png);
  EXPECT_EQ(png->width, 7);
  EXPECT_EQ(png->height, 3);
  // A JPEG: an APP0 segment, then a baseline frame of 640 x 480.
  const std::string jpeg = std::string("\xFF\xD8\xFF\xE0", 4) + be16(16) + std::string(14, 'j') +
                           "\xFF\xC0" + be16(17) + "\x08" + be16(480) + be16(640) +
                           std::string(12, '\0');
  const auto j = header(jpeg);
  ASSERT_TRUE(j);
  EXPECT_EQ(j->format, PictureFormat::jpeg);
  EXPECT_EQ(j->width, 640);
  EXPECT_EQ(j->height, 480);
  // TIFF both ways round: width as a SHORT, length as a LONG.
  const std::string tiff_le = std::string("II*\0", 4) + le32(8) + le16(2) + le16(256) + le16(3) +
                              le32(1) + le16(300) + le16(0) + le16(257) + le16(4) + le32(1) +
                              le32(200) + le32(0);
  const std::string tiff_be = std::string("MM\0*", 4) + be32(8) + be16(2) + be16(256) + be16(3) +
                              be32(1) + be16(300) + be16(0) + be16(257) + be16(4) + be32(1) +
                              be32(200) + be32(0);
  for (const std::string& t : {tiff_le, tiff_be}) {
    const auto h = header(t);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->format, PictureFormat::tiff);
    EXPECT_EQ(h->width, 300);
    EXPECT_EQ(h->height, 200);
  }
  // A BMP stored top row first (a negative height).
  const std::string bmp = "BM" + le32(0) + le32(0) + le32(54) + le32(40) + le32(12) +
                          le32(static_cast<uint32_t>(-5)) + std::string(28, '\0');
  const auto b = header(bmp);
  ASSERT_TRUE(b);
  EXPECT_EQ(b->width, 12);
  EXPECT_EQ(b->height, 5);
}

TEST(PictureGate, OtherFormatsAndBrokenHeadersAreRefused) {
  const std::string png = test::grey_png(7, 3, [](int, int) { return 9; });
  for (const std::string& bad : {
           std::string("\x01\xDA\x01\x01", 4) + std::string(508, '\0'),  // SGI
           std::string("\x53\x80\xF6\x34", 4) + std::string(100, '\0'),  // Softimage PIC
           std::string("SDPX") + std::string(2044, '\0'),                // DPX
           std::string("GIF89a") + std::string(20, '\0'),
           png.substr(0, 20),                          // cut short
           std::string("\xFF\xD8\xFF\xD9", 4),         // a JPEG with no frame
           std::string("II*\0", 4) + le32(1u << 30),   // IFD beyond the end
           std::string("BM") + std::string(30, '\0'),  // no size
           std::string(),
       }) {
    std::string why;
    EXPECT_FALSE(read_picture_header(bad, why)) << why;
    EXPECT_FALSE(why.empty());
  }
  // Whatever the bytes, the gate answers and never reads past them.
  std::mt19937 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string bytes = trial % 2 ? png : std::string("\xFF\xD8\xFF", 3);
    bytes.resize(rng() % 64);
    for (char& c : bytes)
      if (rng() % 4 == 0) c = static_cast<char>(rng());
    std::string why;
    (void)read_picture_header(bytes, why);
  }
}

}  // namespace
}  // namespace curdle
