#include "export/mask_image.h"

#include <algorithm>

#include "curdle/error.h"
#include "export/image.h"
#include "layout/merge_runs.h"

namespace curdle {
namespace {
constexpr uint64_t kMaxMaskFileBytes = uint64_t{64} << 20;
}

std::vector<Rect> read_mask_openings(const std::filesystem::path& path, double wall_width,
                                     double wall_height, const SourceLocation& where,
                                     uint64_t max_bytes) {
  // A device or a pipe (/dev/zero) would be read forever: regular files of bounded size only.
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(where, "cannot read the mask image " + path.string() + ": no such file");
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(where, "the mask image " + path.string() + " is not a regular file");
  const uint64_t file_bytes = std::filesystem::file_size(path, ec);
  if (ec || file_bytes > kMaxMaskFileBytes)
    throw InputError(where, "the mask image " + path.string() + " is larger than 64 MiB");
  ImageSize size;
  try {
    size = read_image_size(path);
  } catch (const std::runtime_error& e) {
    throw InputError(where, "cannot read the mask image " + path.string() + ": " + e.what() +
                                " (any image OpenImageIO reads: PNG, TIFF, JPEG, ...)");
  }
  // Decoded as floats per channel, then luminance and the grid of openings: 4 bytes each.
  const uint64_t pixels = static_cast<uint64_t>(std::max(0, size.width)) *
                          static_cast<uint64_t>(std::max(0, size.height));
  const uint64_t need = pixels * (4 * static_cast<uint64_t>(std::max(1, size.channels)) + 8);
  if (pixels == 0 || pixels > (uint64_t{1} << 32) || need > max_bytes)
    throw ResourceLimitError(
        where, "the mask image is " + std::to_string(size.width) + " x " +
                   std::to_string(size.height) + " pixels, which would take about " +
                   std::to_string(need >> 20) + " MiB to read, above the memory limit of " +
                   std::to_string(max_bytes >> 20) +
                   " MiB; use a smaller image (a pixel per 10 mm is plenty)");
  LuminanceImage image;
  try {
    image = read_luminance(path);
  } catch (const std::runtime_error& e) {
    throw InputError(where, "cannot read the mask image " + path.string() + ": " + e.what() +
                                " (any image OpenImageIO reads: PNG, TIFF, JPEG, ...)");
  }
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
