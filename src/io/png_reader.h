// PNG pictures read in process with libpng (one small library over zlib), so that a mask or
// a picture in PNG, the usual case, does not load OpenImageIO and the 250 libraries it maps:
// on a façade laid through a PNG mask that loading was 85 % of the whole run. The pixels are
// what OpenImageIO's PNG reader gives (a palette as RGB, grey under 8 bits as 8, transparency
// as alpha, 16 bits kept, no gamma applied), so either reader makes the same LuminanceImage.
#pragma once

#include <string>

#include "io/image.h"

namespace curdle {

// Throw std::runtime_error with libpng's message when the bytes are not a PNG it reads.
LuminanceImage read_png_luminance(const std::string& bytes);
ImageSize read_png_size(const std::string& bytes);

}  // namespace curdle
