// libcurdle_image.so: the only code that touches OpenImageIO. Loaded on demand by image.cpp.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "export/image.h"

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
  image->width = w;
  image->height = h;
  image->luminance.resize(static_cast<size_t>(w) * h);
  for (size_t i = 0; i < image->luminance.size(); ++i) {
    const float* p = &pixels[i * channels];
    image->luminance[i] = channels >= 3 ? 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] : p[0];
  }
  if (channels < 3) return true;
  // A few flat colours: kept, so that red and blue of one luminance stay apart.
  auto byte = [](float v) {
    return static_cast<uint32_t>(std::lround(std::clamp(v, 0.f, 1.f) * 255));
  };
  image->colour.resize(image->luminance.size());
  for (size_t i = 0; i < image->luminance.size(); ++i) {
    const float* p = &pixels[i * channels];
    const uint32_t rgb = byte(p[0]) << 16 | byte(p[1]) << 8 | byte(p[2]);
    auto at = std::find(image->palette.begin(), image->palette.end(), rgb);
    if (at == image->palette.end()) {
      if (image->palette.size() == curdle::kMostFlatColours) {
        image->colour.clear(), image->palette.clear();
        break;
      }
      at = image->palette.insert(image->palette.end(), rgb);
    }
    image->colour[i] = static_cast<uint8_t>(at - image->palette.begin());
  }
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
