#include "io/png_reader.h"

#include <png.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "io/luminance.h"

namespace curdle {
namespace {

struct Source {
  const std::string& bytes;
  size_t at = 0;
};

struct Decoded {
  int width = 0, height = 0, channels = 0, depth = 0;
  std::vector<unsigned char> raw;  // rows of `channels` samples of `depth` bits, big-endian
  std::vector<png_bytep> rows;     // where each row of `raw` starts, for libpng
  std::string error;
};

void read_bytes(png_structp png, png_bytep out, png_size_t n) {
  auto* source = static_cast<Source*>(png_get_io_ptr(png));
  if (n > source->bytes.size() - source->at) png_error(png, "the file ends early");
  std::memcpy(out, source->bytes.data() + source->at, n);
  source->at += n;
}

void on_error(png_structp png, png_const_charp message) {
  static_cast<Decoded*>(png_get_error_ptr(png))->error = message;
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

// libpng reports errors by longjmp: everything this frame changes after setjmp lives behind
// `out`, so that nothing here is left half-made when it jumps back.
bool decode(const std::string& bytes, bool pixels, Decoded* out) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, out, on_error, on_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  Source source{bytes};
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_read_fn(png, &source, read_bytes);
  png_read_info(png, info);
  png_set_expand(png);  // a palette to RGB, grey under 8 bits to 8, transparency to alpha
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  out->width = static_cast<int>(png_get_image_width(png, info));
  out->height = static_cast<int>(png_get_image_height(png, info));
  out->channels = png_get_channels(png, info);
  out->depth = png_get_bit_depth(png, info);
  if (pixels) {
    const size_t stride = png_get_rowbytes(png, info);
    out->raw.resize(stride * static_cast<size_t>(out->height));
    out->rows.resize(static_cast<size_t>(out->height));
    for (size_t y = 0; y < out->rows.size(); ++y) out->rows[y] = out->raw.data() + y * stride;
    png_read_image(png, out->rows.data());
    png_read_end(png, nullptr);
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

Decoded decoded(const std::string& bytes, bool pixels) {
  Decoded d;
  if (!decode(bytes, pixels, &d))
    throw std::runtime_error(d.error.empty() ? std::string("not a readable png file") : d.error);
  return d;
}

// Colour times alpha, in whole samples rounded down, as OpenImageIO's PNG reader associates
// them: a transparent part of a mask reads as black.
template <class Sample>
void associate_alpha(Sample* samples, size_t pixels, int channels, unsigned most) {
  for (size_t p = 0; p < pixels; ++p, samples += channels)
    for (int c = 0; c + 1 < channels; ++c)
      samples[c] = static_cast<Sample>(unsigned{samples[c]} * samples[channels - 1] / most);
}

}  // namespace

LuminanceImage read_png_luminance(const std::string& bytes) {
  Decoded d = decoded(bytes, true);
  const size_t count = static_cast<size_t>(d.width) * d.height;
  const bool alpha = d.channels == 2 || d.channels == 4;
  std::vector<float> pixels(count * d.channels);
  // Samples to 0..1 as OpenImageIO scales them: times 1/255 or 1/65535.
  if (d.depth == 16) {
    std::vector<uint16_t> wide(pixels.size());
    for (size_t i = 0; i < wide.size(); ++i)
      wide[i] = static_cast<uint16_t>(d.raw[2 * i] << 8 | d.raw[2 * i + 1]);
    if (alpha) associate_alpha(wide.data(), count, d.channels, 65535);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = wide[i] * (1.0f / 65535.0f);
  } else {
    if (alpha) associate_alpha(d.raw.data(), count, d.channels, 255);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = d.raw[i] * (1.0f / 255.0f);
  }
  return luminance_of(pixels, d.width, d.height, d.channels);
}

ImageSize read_png_size(const std::string& bytes) {
  const Decoded d = decoded(bytes, false);
  return {d.width, d.height, d.channels};
}

}  // namespace curdle
