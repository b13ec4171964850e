// Each format's header as its specification lays it out: PNG (ISO/IEC 15948, the IHDR chunk),
// JPEG (ITU-T T.81, the SOFn segment), TIFF 6.0 (the first IFD's ImageWidth and ImageLength)
// and BMP (the BITMAPINFOHEADER or BITMAPCOREHEADER).
#include "export/picture_gate.h"

#include <cstdlib>

namespace curdle {
namespace {

std::optional<PictureHeader> refuse(std::string& why, const char* reason) {
  why = reason;
  return std::nullopt;
}

// Reads of fixed-width integers that never pass the end of the bytes.
struct Bytes {
  std::string_view b;
  bool little = false;
  bool has(uint64_t at, uint64_t n) const { return at <= b.size() && n <= b.size() - at; }
  uint32_t u8(uint64_t at) const { return static_cast<uint8_t>(b[at]); }
  uint32_t u16(uint64_t at) const {
    return little ? u8(at) | u8(at + 1) << 8 : u8(at) << 8 | u8(at + 1);
  }
  uint32_t u32(uint64_t at) const {
    return little ? u16(at) | u16(at + 2) << 16 : u16(at) << 16 | u16(at + 2);
  }
};

std::optional<PictureHeader> png(const Bytes& f, std::string& why) {
  if (!f.has(16, 8) || f.b.substr(12, 4) != "IHDR")
    return refuse(why, "its PNG header is cut short");
  return PictureHeader{PictureFormat::png, f.u32(16), f.u32(20)};
}

std::optional<PictureHeader> jpeg(const Bytes& f, std::string& why) {
  uint64_t at = 2;
  while (f.has(at, 4)) {
    if (f.u8(at) != 0xFF) return refuse(why, "its JPEG segments are broken");
    const uint32_t marker = f.u8(at + 1);
    if (marker == 0xFF) {  // fill byte
      ++at;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // segments without a length
      at += 2;
      continue;
    }
    if (marker == 0xD9 || marker == 0xDA) break;  // the image ends or its data starts: no SOF
    const uint32_t length = f.u16(at + 2);
    if (length < 2) return refuse(why, "its JPEG segments are broken");
    const bool frame =
        marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (frame) {
      if (!f.has(at + 4, 5)) break;
      return PictureHeader{PictureFormat::jpeg, f.u16(at + 7), f.u16(at + 5)};
    }
    at += 2 + length;
  }
  return refuse(why, "its JPEG header has no frame size");
}

std::optional<PictureHeader> tiff(Bytes f, std::string& why) {
  f.little = f.b[0] == 'I';
  if (!f.has(0, 8)) return refuse(why, "its TIFF header is cut short");
  const uint32_t ifd = f.u32(4);
  if (!f.has(ifd, 2)) return refuse(why, "its TIFF directory lies beyond the file");
  const uint32_t entries = f.u16(ifd);
  int64_t width = 0, height = 0;
  for (uint32_t i = 0; i < entries; ++i) {
    const uint64_t e = ifd + 2 + uint64_t{12} * i;
    if (!f.has(e, 12)) return refuse(why, "its TIFF directory is cut short");
    const uint32_t tag = f.u16(e), type = f.u16(e + 2);
    if (tag != 256 && tag != 257) continue;
    // SHORT values stand in the field's first two bytes, LONG in all four.
    const uint32_t value = type == 3 ? f.u16(e + 8) : type == 4 ? f.u32(e + 8) : 0;
    (tag == 256 ? width : height) = value;
  }
  return PictureHeader{PictureFormat::tiff, width, height};
}

std::optional<PictureHeader> bmp(Bytes f, std::string& why) {
  f.little = true;
  if (!f.has(14, 12)) return refuse(why, "its BMP header is cut short");
  const uint32_t header = f.u32(14);
  if (header == 12) return PictureHeader{PictureFormat::bmp, f.u16(18), f.u16(20)};
  if (header < 40) return refuse(why, "its BMP header is of an unknown kind");
  // Height is signed: a negative one is a picture stored top row first.
  const auto width = static_cast<int32_t>(f.u32(18)), height = static_cast<int32_t>(f.u32(22));
  return PictureHeader{PictureFormat::bmp, width, std::llabs(static_cast<int64_t>(height))};
}

}  // namespace

std::optional<PictureHeader> read_picture_header(std::string_view bytes, std::string& why) {
  const Bytes f{bytes};
  std::optional<PictureHeader> h;
  if (bytes.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8))
    h = png(f, why);
  else if (bytes.substr(0, 3) == "\xFF\xD8\xFF")
    h = jpeg(f, why);
  else if (bytes.substr(0, 4) == std::string_view("II*\0", 4) ||
           bytes.substr(0, 4) == std::string_view("MM\0*", 4))
    h = tiff(f, why);
  else if (bytes.substr(0, 2) == "BM")
    h = bmp(f, why);
  else
    why = std::string("it is not a ") + kPictureFormats + " file (read by its first bytes)";
  if (h && (h->width <= 0 || h->height <= 0)) {
    why = "its header gives no size";
    h.reset();
  }
  return h;
}

}  // namespace curdle
