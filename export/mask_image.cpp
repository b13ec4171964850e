#include "export/mask_image.h"

#include <OpenImageIO/imageio.h>

#include "curdle/error.h"
#include "export/svg.h"

namespace curdle {

std::vector<Rect> read_mask_openings(const std::filesystem::path& image, double wall_width,
                                     double wall_height, const SourceLocation& where) {
  auto in = OIIO::ImageInput::open(image.string());
  if (!in)
    throw InputError(where, "cannot read the mask image " + image.string() + ": " +
                                OIIO::geterror() +
                                " (any image OpenImageIO reads: PNG, TIFF, JPEG, ...)");
  const OIIO::ImageSpec& spec = in->spec();
  const int w = spec.width, h = spec.height, channels = spec.nchannels;
  std::vector<float> pixels(static_cast<size_t>(w) * h * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw InputError(where, "cannot read the mask image " + image.string() + ": " + in->geterror());
  // Dark pixels (luminance < 1/2) are openings; rows of them are merged into rectangles.
  std::vector<int> grid(static_cast<size_t>(w) * h, -1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* p = &pixels[(static_cast<size_t>(y) * w + x) * channels];
      const float lum = channels >= 3 ? 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] : p[0];
      if (lum < 0.5f) grid[static_cast<size_t>(y) * w + x] = 1;
    }
  std::vector<Rect> openings;
  const double sx = wall_width / w, sy = wall_height / h;
  for (const GridRect& g : merge_runs(grid, h, w))  // image rows run down the wall
    openings.push_back(Rect{g.column0 * sx, wall_height - (g.row1 + 1) * sy,
                            (g.column1 - g.column0 + 1) * sx, (g.row1 - g.row0 + 1) * sy});
  return openings;
}

}  // namespace curdle
