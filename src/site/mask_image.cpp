#include "site/mask_image.h"

#include <algorithm>

#include "curdle/error.h"
#include "io/bounded_image.h"
#include "layout/merge_runs.h"

namespace curdle {
std::vector<Rect> read_mask_openings(const std::filesystem::path& path, double wall_width,
                                     double wall_height, const SourceLocation& where,
                                     uint64_t max_bytes) {
  const LuminanceImage image = read_bounded_luminance(path, "the mask image", where, max_bytes);
  const int w = image.width, h = image.height;
  // Dark pixels (luminance < 1/2) are openings; rows of them are merged into rectangles.
  std::vector<int> grid(static_cast<size_t>(w) * h, -1);
  for (size_t i = 0; i < grid.size(); ++i)
    if (image.luminance[i] < 0.5f) grid[i] = 1;
  std::vector<Rect> openings;
  const double sx = wall_width / w, sy = wall_height / h;
  for (const GridRect& g : merge_runs(grid, h, w))  // image rows run down the wall
    openings.push_back(Rect{g.column0 * sx, wall_height - (g.row1 + 1) * sy,
                            (g.column1 - g.column0 + 1) * sx, (g.row1 - g.row0 + 1) * sy});
  return openings;
}

}  // namespace curdle
