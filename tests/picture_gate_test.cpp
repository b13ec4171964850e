// Tests of picture_gate.h: the four formats are known by their first bytes and sized by their
// headers, whatever their names; everything else, and every header cut short, is refused before
// a decoder sees it.
#include "io/picture_gate.h"

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

// Work a decoder would do before any pixel is bounded from the bytes: a JPEG's scans, a PNG's
// compressed text chunks, a TIFF's planes and blocks. Just under each bound passes.
TEST(PictureGate, DecodingWorkIsBoundedBeforeTheDecoder) {
  const std::string frame = std::string("\xFF\xD8\xFF\xC2", 4) + be16(11) + std::string(1, 8) +
                            be16(16) + be16(16) + std::string("\x01\x01\x11\x00", 4);
  // A scan: its header, then entropy data holding stuffed bytes and a restart marker.
  const std::string scan = std::string("\xFF\xDA", 2) + be16(8) +
                           std::string("\x01\x01\x00\x00\x3F\x00", 6) +
                           std::string("\x12\xFF\x00\x34\xFF\xD0\x56", 7);
  auto jpeg = [&](int scans) {
    std::string bytes = frame;
    for (int i = 0; i < scans; ++i) bytes += scan;
    return bytes + std::string("\xFF\xD9", 2);
  };
  EXPECT_TRUE(header(jpeg(kMostJpegScans)));
  std::string why;
  EXPECT_FALSE(read_picture_header(jpeg(kMostJpegScans + 1), why));
  EXPECT_NE(why.find("more than 256 scans"), std::string::npos) << why;

  const std::string png = test::grey_png(7, 3, [](int, int) { return 9; });
  auto with_chunks = [&](int n, const std::string& type) {
    const std::string chunk = be32(4) + type + "abcd" + be32(0);
    std::string bytes = png.substr(0, 33);  // the signature and IHDR
    for (int i = 0; i < n; ++i) bytes += chunk;
    return bytes + png.substr(33);
  };
  EXPECT_TRUE(header(with_chunks(kMostPngTextChunks, "zTXt")));
  EXPECT_TRUE(header(with_chunks(1000, "tEXt")));  // plain text is not inflated
  for (const char* type : {"zTXt", "iTXt", "iCCP"}) {
    EXPECT_FALSE(read_picture_header(with_chunks(kMostPngTextChunks + 1, type), why)) << type;
    EXPECT_NE(why.find("compressed text"), std::string::npos) << why;
  }

  auto tiff = [](const std::vector<std::pair<uint32_t, uint32_t>>& tags) {
    std::string bytes = std::string("II*\0", 4) + le32(8) + le16(tags.size());
    for (const auto& [tag, value] : tags) bytes += le16(tag) + le16(4) + le32(1) + le32(value);
    return bytes + le32(0);
  };
  EXPECT_TRUE(header(tiff({{256, 64}, {257, 64}, {277, 16}, {284, 2}, {322, 16}, {323, 16}})));
  EXPECT_FALSE(read_picture_header(tiff({{256, 16}, {257, 16}, {277, 65535}, {284, 2}}), why));
  EXPECT_NE(why.find("65535 samples"), std::string::npos) << why;
  // 2^16 x 2^16 pixels in strips of a row, in 16 planes: 2^20 blocks pass; in 16 x 16 tiles of
  // 16 planes, 2^28 do not.
  EXPECT_TRUE(header(tiff({{256, 65536}, {257, 65536}, {277, 16}, {284, 2}, {278, 1}})));
  EXPECT_FALSE(read_picture_header(
      tiff({{256, 65536}, {257, 65536}, {277, 16}, {284, 2}, {322, 16}, {323, 16}}), why));
  EXPECT_NE(why.find("tiles or strips"), std::string::npos) << why;
}

// The decoder is named by the bytes: what OpenImageIO calls each format.
TEST(PictureGate, TheDecoderIsNamedByTheFormat) {
  EXPECT_STREQ(decoder_name(PictureFormat::png), "png");
  EXPECT_STREQ(decoder_name(PictureFormat::jpeg), "jpeg");
  EXPECT_STREQ(decoder_name(PictureFormat::tiff), "tiff");
  EXPECT_STREQ(decoder_name(PictureFormat::bmp), "bmp");
}

}  // namespace
}  // namespace curdle
