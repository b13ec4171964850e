#include "app/picture_cells.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>

#include "curdle/error.h"
#include "curdle/measure.h"
#include "curdle/palette.h"
#include "export/report/measure_files.h"

namespace curdle::app {
namespace {

// Whether every k x k block of the picture is one shade (and one colour, when it keeps them).
bool blocks_of(const LuminanceImage& image, int k) {
  const int64_t w = image.width;
  for (int64_t y = 0; y < image.height; ++y)
    for (int64_t x = 0; x < w; ++x) {
      const size_t at = static_cast<size_t>(y * w + x);
      const size_t corner = static_cast<size_t>((y - y % k) * w + (x - x % k));
      if (image.luminance[at] != image.luminance[corner]) return false;
      if (!image.colour.empty() && image.colour[at] != image.colour[corner]) return false;
    }
  return true;
}

int found_cell_pixels(const LuminanceImage& image) {
  const int g = std::gcd(image.width, image.height);
  for (int k = g; k >= 2; --k)
    if (g % k == 0 && blocks_of(image, k)) return k;
  return 1;
}

Rgb rgb_of(uint32_t packed) {
  return Rgb{static_cast<uint8_t>(packed >> 16), static_cast<uint8_t>(packed >> 8),
             static_cast<uint8_t>(packed)};
}

double distance2(const Rgb& a, const Rgb& b) {
  const double r = a.r - b.r, g = a.g - b.g, bl = a.b - b.b;
  return r * r + g * g + bl * bl;
}

double luminance_of(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// Each palette colour's value: the lightest is the ground; `curds` of the others are the curds'
// own colours, chosen so that the library's blends of them (palette.h) come nearest the rest.
// Empty when the colours cannot be read so (too few).
std::vector<uint16_t> values_by_colour(const std::vector<uint32_t>& palette, int curds,
                                       std::vector<Rgb>& curd_rgb) {
  std::vector<Rgb> colours;
  for (uint32_t c : palette) colours.push_back(rgb_of(c));
  std::vector<size_t> order(colours.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return luminance_of(colours[a]) > luminance_of(colours[b]);
  });
  const size_t ground = order[0];
  std::vector<size_t> rest(order.begin() + 1, order.end());
  if (rest.size() < static_cast<size_t>(curds)) return {};
  double best = std::numeric_limits<double>::infinity();
  std::vector<uint16_t> best_values;
  // Ordered choices of `curds` colours among the rest: at most 15 * 14 * 13 * 12.
  std::vector<size_t> pick(static_cast<size_t>(curds));
  std::function<void(size_t)> choose = [&](size_t depth) {
    if (depth == pick.size()) {
      std::vector<CurdSpec> specs(pick.size());
      for (size_t c = 0; c < pick.size(); ++c) specs[c].colour = colours[pick[c]];
      std::vector<Rgb> predicted = value_colours(specs);
      predicted[0] = colours[ground];
      double cost = 0;
      std::vector<uint16_t> values(colours.size());
      for (size_t i = 0; i < colours.size(); ++i) {
        double nearest = std::numeric_limits<double>::infinity();
        for (size_t v = 0; v < predicted.size(); ++v)
          if (const double d = distance2(colours[i], predicted[v]); d < nearest)
            nearest = d, values[i] = static_cast<uint16_t>(v);
        cost += nearest;
      }
      if (cost < best) {
        best = cost, best_values = values;
        curd_rgb.clear();
        for (size_t c : pick) curd_rgb.push_back(colours[c]);
      }
      return;
    }
    for (size_t r : rest)
      if (std::find(pick.begin(), pick.begin() + static_cast<std::ptrdiff_t>(depth), r) ==
          pick.begin() + static_cast<std::ptrdiff_t>(depth)) {
        pick[depth] = r;
        choose(depth + 1);
      }
  };
  choose(0);
  return best_values;
}

// The picture's cells (k x k pixels each, k found when `cell_pixels` is 0): each cell's top-left
// pixel's luminance and colour (a preview's cells are one shade).
PictureCells cells_of(const LuminanceImage& image, int cell_pixels, std::vector<float>& luminance,
                      std::vector<uint8_t>& colour) {
  PictureCells out;
  const int k = cell_pixels > 0 ? cell_pixels : found_cell_pixels(image);
  if (image.width % k != 0 || image.height % k != 0)
    throw InputError(parameter("cell_pixels"), "the picture's " + std::to_string(image.width) +
                                                   " x " + std::to_string(image.height) +
                                                   " pixels are not whole cells of " +
                                                   std::to_string(k) + " x " + std::to_string(k));
  out.pixels_per_cell = k;
  out.width = image.width / k, out.height = image.height / k;
  for (int64_t y = 0; y < out.height; ++y)
    for (int64_t x = 0; x < out.width; ++x) {
      const size_t at = static_cast<size_t>(y * k * image.width + x * k);
      luminance.push_back(image.luminance[at]);
      if (!image.colour.empty()) colour.push_back(image.colour[at]);
    }
  return out;
}

}  // namespace

PictureCells picture_cells(const LuminanceImage& image, int curds, int cell_pixels) {
  std::vector<float> luminance;
  std::vector<uint8_t> colour;
  PictureCells out = cells_of(image, cell_pixels, luminance, colour);
  std::vector<Rgb> curd_rgb;
  const std::vector<uint16_t> by_colour =
      curds >= 2 && !colour.empty() && image.palette.size() <= (size_t{1} << curds)
          ? values_by_colour(image.palette, curds, curd_rgb)
          : std::vector<uint16_t>{};
  if (!by_colour.empty()) {
    out.by_colour = true;
    for (uint8_t c : colour) out.values.push_back(by_colour[c]);
    for (const Rgb& c : curd_rgb) out.curd_colours.push_back(hex_colour(c));
    return out;
  }
  std::vector<double> levels;
  out.values = quantise(out.width, out.height, luminance, 1 << curds, levels).values;
  for (int c = 0; c < curds; ++c)
    out.curd_colours.push_back(level_colour(levels[static_cast<size_t>(1) << c]));
  return out;
}

PictureCells picture_tones(const LuminanceImage& image, int tones, int cell_pixels) {
  std::vector<float> luminance;
  std::vector<uint8_t> colour;
  PictureCells out = cells_of(image, cell_pixels, luminance, colour);
  if (!colour.empty() && image.palette.size() <= static_cast<size_t>(tones)) {
    // Its own colours, lightest first.
    std::vector<size_t> order(image.palette.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return luminance_of(rgb_of(image.palette[a])) > luminance_of(rgb_of(image.palette[b]));
    });
    std::vector<uint16_t> tone_of(order.size());
    for (size_t t = 0; t < order.size(); ++t) {
      tone_of[order[t]] = static_cast<uint16_t>(t);
      out.curd_colours.push_back(hex_colour(rgb_of(image.palette[order[t]])));
    }
    for (uint8_t c : colour) out.values.push_back(tone_of[c]);
    out.by_colour = true;
    return out;
  }
  std::vector<double> levels;
  out.values = quantise(out.width, out.height, luminance, tones, levels).values;
  for (const double l : levels) out.curd_colours.push_back(level_colour(l));
  return out;
}

}  // namespace curdle::app
