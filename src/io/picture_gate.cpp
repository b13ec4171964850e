// Each format's header as its specification lays it out: PNG (ISO/IEC 15948, the IHDR chunk),
// JPEG (ITU-T T.81, the SOFn segment), TIFF 6.0 (the first IFD's ImageWidth and ImageLength)
// and BMP (the BITMAPINFOHEADER or BITMAPCOREHEADER).
#include "io/picture_gate.h"

#include <cstdlib>
#include <string>
#include <utility>

namespace curdle {
namespace {

std::optional<PictureHeader> refuse(std::string& why, std::string reason) {
  why = std::move(reason);
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
  // The decoder inflates every compressed text and profile chunk, each up to 8 MB: a thousand
  // of them are a minute of work in a file of a few megabytes. Counted first.
  int compressed = 0;
  for (uint64_t at = 8; f.has(at, 8);) {
    const uint64_t length = f.u32(at);
    const std::string_view type = f.b.substr(at + 4, 4);
    if (type == "IEND") break;
    if ((type == "zTXt" || type == "iTXt" || type == "iCCP") && ++compressed > kMostPngTextChunks)
      return refuse(why, "it holds more than " + std::to_string(kMostPngTextChunks) +
                             " compressed text or profile chunks (zTXt, iTXt, iCCP); save the "
                             "picture without its metadata");
    at += 12 + length;
  }
  return PictureHeader{PictureFormat::png, f.u32(16), f.u32(20)};
}

// One walk over the segments: the frame's size (SOFn), then each scan (SOS and its entropy-coded
// data, up to the next marker: a 0xFF that is neither stuffing nor a restart) counted, since a
// progressive picture is decoded once per scan over the whole picture: a few dozen in any
// camera's or editor's file, 400,000 in a crafted one (minutes of work). Past the frame, what
// cannot be walked is left to the decoder, which will say so.
std::optional<PictureHeader> jpeg(const Bytes& f, std::string& why) {
  std::optional<PictureHeader> frame;
  int scans = 0;
  uint64_t at = 2;
  while (f.has(at, frame ? 2 : 4)) {
    if (f.u8(at) != 0xFF) {
      if (frame) break;
      return refuse(why, "its JPEG segments are broken");
    }
    const uint32_t marker = f.u8(at + 1);
    if (marker == 0xFF) {  // fill byte
      ++at;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // segments without a length
      at += 2;
      continue;
    }
    if (marker == 0xD9 || !f.has(at, 4)) break;  // the image ends
    if (marker == 0xDA) {
      if (!frame) break;  // its data starts before any frame: no size
      if (++scans > kMostJpegScans)
        return refuse(why, "it has more than " + std::to_string(kMostJpegScans) +
                               " scans; save it as a baseline JPEG or as PNG");
      at += 2 + f.u16(at + 2);
      size_t next_marker = std::string_view::npos;
      while (f.has(at, 2)) {
        const size_t ff = f.b.find('\xFF', at);
        if (ff == std::string_view::npos || !f.has(ff, 2)) break;
        const uint32_t next = f.u8(ff + 1);
        if (next != 0x00 && next != 0xFF && !(next >= 0xD0 && next <= 0xD7)) {
          next_marker = ff;
          break;
        }
        at = ff + (next == 0xFF ? 1 : 2);
      }
      if (next_marker == std::string_view::npos) break;
      at = next_marker;
      continue;
    }
    const uint32_t length = f.u16(at + 2);
    if (!frame) {
      if (length < 2) return refuse(why, "its JPEG segments are broken");
      const bool sof =
          marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
      if (sof) {
        if (!f.has(at + 4, 5)) break;
        frame = PictureHeader{PictureFormat::jpeg, f.u16(at + 7), f.u16(at + 5)};
      }
    }
    at += 2 + length;
  }
  if (!frame) return refuse(why, "its JPEG header has no frame size");
  return frame;
}

std::optional<PictureHeader> tiff(Bytes f, std::string& why) {
  f.little = f.b[0] == 'I';
  if (!f.has(0, 8)) return refuse(why, "its TIFF header is cut short");
  const uint32_t ifd = f.u32(4);
  if (!f.has(ifd, 2)) return refuse(why, "its TIFF directory lies beyond the file");
  const uint32_t entries = f.u16(ifd);
  int64_t width = 0, height = 0;
  uint64_t samples = 1, planar = 1, tile_width = 0, tile_length = 0, rows_per_strip = 0;
  for (uint32_t i = 0; i < entries; ++i) {
    const uint64_t e = ifd + 2 + uint64_t{12} * i;
    if (!f.has(e, 12)) return refuse(why, "its TIFF directory is cut short");
    const uint32_t tag = f.u16(e), type = f.u16(e + 2);
    // SHORT values stand in the field's first two bytes, LONG in all four.
    const uint32_t value = type == 3 ? f.u16(e + 8) : type == 4 ? f.u32(e + 8) : 0;
    switch (tag) {
      case 256:
        width = value;
        break;
      case 257:
        height = value;
        break;
      case 277:
        samples = value;
        break;
      case 278:
        rows_per_strip = value;
        break;
      case 284:
        planar = value;
        break;
      case 322:
        tile_width = value;
        break;
      case 323:
        tile_length = value;
        break;
      default:
        break;
    }
  }
  if (samples > static_cast<uint64_t>(kMostTiffSamples))
    return refuse(why, "it has " + std::to_string(samples) + " samples per pixel; at most " +
                           std::to_string(kMostTiffSamples));
  // libtiff allocates an offset and a byte count for every tile or strip of every plane before
  // it reads a pixel: their number is bounded here, from the directory's own figures.
  auto blocks = [](uint64_t n, uint64_t per) { return per ? (n + per - 1) / per : n; };
  const uint64_t w = static_cast<uint64_t>(width), h = static_cast<uint64_t>(height);
  uint64_t count = tile_width || tile_length ? blocks(w, tile_width) * blocks(h, tile_length)
                                             : blocks(h, rows_per_strip ? rows_per_strip : h);
  if (planar == 2) count *= samples;
  if (count > kMostTiffBlocks)
    return refuse(why, "it is stored in " + std::to_string(count) + " tiles or strips; at most " +
                           std::to_string(kMostTiffBlocks));
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

const char* decoder_name(PictureFormat format) {
  switch (format) {
    case PictureFormat::png:
      return "png";
    case PictureFormat::jpeg:
      return "jpeg";
    case PictureFormat::tiff:
      return "tiff";
    case PictureFormat::bmp:
      return "bmp";
  }
  return "png";
}

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
