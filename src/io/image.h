// Images in and out: PNG encoding (zlib, png_encoder.cpp), PNG reading (libpng, png_reader.h)
// and reading any other image OpenImageIO reads. OpenImageIO (and the codecs it brings, over
// 250 shared libraries) lives in a module, libcurdle_image.so, loaded the first time such an
// image is read, so that commands that read none start at once.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace curdle {

struct PreviewImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, top row first
};

// The PNG file's bytes; `dpi` > 0 records the resolution so that it prints at size.
std::string encode_png(const PreviewImage& image, double dpi = 0);
// The same from rows made as they are needed: `rows(y, rgb)` fills row y's width * 3 bytes,
// top row first, so that a picture held in another form (a cairo surface) is not copied whole.
using PngRows = std::function<void(int y, uint8_t* rgb)>;
std::string encode_png(int width, int height, const PngRows& rows, double dpi = 0);

// An image's luminance (Rec. 709), row-major, top row first, from 0 (black) to 1 (white). A
// colour picture of at most kMostFlatColours colours (a preview, a drawing) also keeps them:
// each pixel's index into `palette` (0xRRGGBB), so that colours of one luminance stay apart.
struct LuminanceImage {
  int width = 0, height = 0;
  std::vector<float> luminance;
  std::vector<uint8_t> colour;    // per pixel; empty: grey, or too many colours
  std::vector<uint32_t> palette;  // the colours `colour` indexes
};
inline constexpr size_t kMostFlatColours = 16;
// Decoded by the reader of `format` ("png", "jpeg", "tiff", "bmp": what the bytes are, from
// picture_gate.h), never by the file's name, with OpenImageIO's reader (a PNG whose bytes are
// in hand is read in process instead: png_reader.h). Throws std::runtime_error with the
// reader's message when the file cannot be read.
LuminanceImage read_luminance(const std::filesystem::path& path, const char* format);

// An image's size from its header, without decoding it (for memory guards).
struct ImageSize {
  int width = 0, height = 0, channels = 0;
};
ImageSize read_image_size(const std::filesystem::path& path, const char* format);

// The module's entry points (C linkage so that dlsym finds them by name).
extern "C" {
using ReadLuminanceFn = bool (*)(const char* path, const char* format, LuminanceImage* image,
                                 std::string* error);
using ReadSizeFn = bool (*)(const char* path, const char* format, ImageSize* size,
                            std::string* error);
}

}  // namespace curdle
