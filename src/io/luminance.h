// Decoded pixels to a LuminanceImage, the same for every decoder (the OpenImageIO module and
// the PNG reader): Rec. 709 luminance of the first three channels (the first alone for grey),
// and the flat colours of a picture of at most kMostFlatColours of them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "io/image.h"

namespace curdle {

// `pixels`: w x h pixels of `channels` floats from 0 to 1, top row first.
inline LuminanceImage luminance_of(const std::vector<float>& pixels, int w, int h, int channels) {
  LuminanceImage image;
  image.width = w;
  image.height = h;
  image.luminance.resize(static_cast<size_t>(w) * h);
  for (size_t i = 0; i < image.luminance.size(); ++i) {
    const float* p = &pixels[i * channels];
    image.luminance[i] = channels >= 3 ? 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] : p[0];
  }
  if (channels < 3) return image;
  // A few flat colours: kept, so that red and blue of one luminance stay apart.
  auto byte = [](float v) {
    return static_cast<uint32_t>(std::lround(std::clamp(v, 0.f, 1.f) * 255));
  };
  image.colour.resize(image.luminance.size());
  for (size_t i = 0; i < image.luminance.size(); ++i) {
    const float* p = &pixels[i * channels];
    const uint32_t rgb = byte(p[0]) << 16 | byte(p[1]) << 8 | byte(p[2]);
    auto at = std::find(image.palette.begin(), image.palette.end(), rgb);
    if (at == image.palette.end()) {
      if (image.palette.size() == kMostFlatColours) {
        image.colour.clear(), image.palette.clear();
        break;
      }
      at = image.palette.insert(image.palette.end(), rgb);
    }
    image.colour[i] = static_cast<uint8_t>(at - image.palette.begin());
  }
  return image;
}

}  // namespace curdle
