// libcurdle_image.so: the only code that touches OpenImageIO. Loaded on demand by image.cpp.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "io/image.h"
#include "io/luminance.h"

using curdle::ImageSize;
using curdle::LuminanceImage;

namespace {

// The reader of `format`, opened on `path`: OpenImageIO would otherwise try the reader its
// extension names first (LibRaw for .dng, DICOM for .dcm) whatever the bytes are.
std::unique_ptr<OIIO::ImageInput> open_as(const char* path, const char* format,
                                          std::string* error) {
  auto in = OIIO::ImageInput::create(format);
  OIIO::ImageSpec spec;
  if (!in || !in->open(path, spec)) {
    *error = in ? in->geterror() : OIIO::geterror();
    if (error->empty()) *error = std::string("not a readable ") + format + " file";
    return nullptr;
  }
  return in;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) bool curdle_image_read_luminance_as(
    const char* path, const char* format, LuminanceImage* image, std::string* error) {
  auto in = open_as(path, format, error);
  if (!in) return false;
  const OIIO::ImageSpec& spec = in->spec();
  const int w = spec.width, h = spec.height, channels = spec.nchannels;
  std::vector<float> pixels(static_cast<size_t>(w) * h * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) {
    *error = in->geterror();
    return false;
  }
  *image = curdle::luminance_of(pixels, w, h, channels);
  return true;
}

extern "C" __attribute__((visibility("default"))) bool curdle_image_read_size_as(
    const char* path, const char* format, ImageSize* size, std::string* error) {
  auto in = open_as(path, format, error);
  if (!in) return false;
  size->width = in->spec().width;
  size->height = in->spec().height;
  size->channels = in->spec().nchannels;
  return true;
}
