// The gate every picture passes before a decoder sees it. OpenImageIO reads dozens of formats,
// and some of its readers (SGI, Softimage, DPX among them) abort or crash on a crafted file:
// curdle takes only PNG, JPEG, TIFF and BMP, known by their first bytes whatever the file's
// name, and reads each one's size from its own header, so that a picture too large or not a
// picture at all is refused before it is decoded.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace curdle {

enum class PictureFormat { png, jpeg, tiff, bmp };

struct PictureHeader {
  PictureFormat format = PictureFormat::png;
  int64_t width = 0, height = 0;
};

// Bounds on work the decoders would do before any pixel: a progressive JPEG is decoded once per
// scan; libpng inflates every compressed text chunk; libtiff allocates an offset per tile or
// strip of every sample plane.
inline constexpr int kMostJpegScans = 256;
inline constexpr int kMostPngTextChunks = 16;
inline constexpr int kMostTiffSamples = 16;
inline constexpr uint64_t kMostTiffBlocks = uint64_t{1} << 24;

// The name OpenImageIO knows the format by ("png", "jpeg", "tiff", "bmp"): the decoder is
// chosen by what the bytes are, never by the file's name.
const char* decoder_name(PictureFormat format);

// "PNG, JPEG, TIFF or BMP": what messages say is allowed.
inline constexpr const char* kPictureFormats = "PNG, JPEG, TIFF or BMP";

// The format and size of the picture whose file is `bytes` (the whole file: a TIFF's size may
// stand at its end), or std::nullopt with `why` saying what is wrong: not one of the formats,
// or a header that is cut short or says a size of 0.
std::optional<PictureHeader> read_picture_header(std::string_view bytes, std::string& why);

}  // namespace curdle
