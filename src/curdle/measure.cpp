#include "curdle/measure.h"

#include <algorithm>
#include <cmath>

#include "curdle/box_levels.h"

namespace curdle {

ValueGrid quantise(int64_t width, int64_t height, const std::vector<float>& luminance, int count,
                   std::vector<double>& levels) {
  // Lloyd's k-means on a histogram of the luminance (4096 bins: finer than any 8-bit or 12-bit
  // picture's steps), centres starting evenly from the lightest to the darkest luminance.
  constexpr int kBins = 4096;
  auto bin_of = [](float l) {
    return std::clamp(static_cast<int>(std::lround(l * (kBins - 1))), 0, kBins - 1);
  };
  std::vector<uint64_t> histogram(kBins, 0);
  for (float l : luminance) ++histogram[static_cast<size_t>(bin_of(l))];
  int lo = 0, hi = kBins - 1;
  while (lo < hi && !histogram[static_cast<size_t>(lo)]) ++lo;
  while (hi > lo && !histogram[static_cast<size_t>(hi)]) --hi;
  levels.assign(static_cast<size_t>(count), 0.0);
  for (int v = 0; v < count; ++v)
    levels[static_cast<size_t>(v)] =
        (hi - (hi - lo) * static_cast<double>(v) / std::max(1, count - 1)) / (kBins - 1);
  std::vector<uint16_t> value_of_bin(kBins, 0);
  for (int round = 0; round < 100; ++round) {
    std::vector<double> sum(levels.size(), 0.0), n(levels.size(), 0.0);
    for (int b = 0; b < kBins; ++b) {
      const double l = static_cast<double>(b) / (kBins - 1);
      size_t best = 0;
      for (size_t v = 1; v < levels.size(); ++v)
        if (std::fabs(l - levels[v]) < std::fabs(l - levels[best])) best = v;
      value_of_bin[static_cast<size_t>(b)] = static_cast<uint16_t>(best);
      sum[best] += l * static_cast<double>(histogram[static_cast<size_t>(b)]);
      n[best] += static_cast<double>(histogram[static_cast<size_t>(b)]);
    }
    bool moved = false;
    for (size_t v = 0; v < levels.size(); ++v) {
      if (n[v] == 0) continue;  // an empty value keeps its centre
      moved |= std::fabs(sum[v] / n[v] - levels[v]) > 1e-12;
      levels[v] = sum[v] / n[v];
    }
    if (!moved) break;
  }
  // Centres keep their order (lightest first): Lloyd's steps never swap neighbours in 1-D.
  ValueGrid grid{width, height, std::vector<uint16_t>(luminance.size(), 0)};
  for (size_t i = 0; i < luminance.size(); ++i)
    grid.values[i] = value_of_bin[static_cast<size_t>(bin_of(luminance[i]))];
  return grid;
}

ValueGrid threshold(int64_t width, int64_t height, const std::vector<float>& luminance, double t) {
  ValueGrid grid{width, height, std::vector<uint16_t>(luminance.size(), 0)};
  for (size_t i = 0; i < luminance.size(); ++i) grid.values[i] = luminance[i] < t ? 1 : 0;
  return grid;
}

std::vector<uint64_t> count_boxes(int64_t width, int64_t height, const std::vector<bool>& inside,
                                  int base, std::vector<int64_t>& sizes) {
  int levels = 0;  // boxes up to the shorter side
  for (int64_t side = 1; side <= std::min(width, height) / base; side *= base) ++levels;
  std::vector<uint64_t> counts;
  sizes.clear();
  for_each_box_level(
      base, 2, Box{{0, 0, 0}, {width, height, 1}}, inside, levels, [&](const BoxLevel& level) {
        sizes.push_back(level.side);
        counts.push_back(
            static_cast<uint64_t>(std::count(level.occupied.begin(), level.occupied.end(), true)));
      });
  return counts;
}

namespace {

// Gliding-box lacunarity E[M^2] / E[M]^2 of `inside` with boxes of side `box` (Allain & Cloitre
// 1991), from a summed-area table; nullopt when no pixel is inside.
std::optional<double> lacunarity(int64_t width, int64_t height, const std::vector<bool>& inside,
                                 int64_t box) {
  std::vector<uint64_t> sat(static_cast<size_t>((width + 1) * (height + 1)), 0);
  auto at = [&](int64_t x, int64_t y) -> uint64_t& {
    return sat[static_cast<size_t>(y * (width + 1) + x)];
  };
  for (int64_t y = 0; y < height; ++y)
    for (int64_t x = 0; x < width; ++x)
      at(x + 1, y + 1) = at(x, y + 1) + at(x + 1, y) - at(x, y) +
                         (inside[static_cast<size_t>(y * width + x)] ? 1 : 0);
  double m1 = 0, m2 = 0, n = 0;
  for (int64_t y = 0; y + box <= height; ++y)
    for (int64_t x = 0; x + box <= width; ++x) {
      const double m = static_cast<double>(at(x + box, y + box) + at(x, y)) -
                       static_cast<double>(at(x, y + box) + at(x + box, y));
      m1 += m, m2 += m * m, n += 1;
    }
  if (m1 <= 0) return std::nullopt;
  return (m2 / n) / ((m1 / n) * (m1 / n));
}

}  // namespace

Measurement measure(const ValueGrid& grid, int count, int base) {
  Measurement m;
  m.width = grid.width, m.height = grid.height, m.base = base;
  // Boxes of a sixteenth of the shorter side (a power of two): large enough to see clumps,
  // small enough for many positions.
  while (m.lacunarity_box * 2 <= std::min(grid.width, grid.height) / 16) m.lacunarity_box *= 2;
  const double pixels = static_cast<double>(grid.width * grid.height);
  size_t ground = 0;
  std::vector<uint64_t> counts(static_cast<size_t>(count), 0);
  for (uint16_t v : grid.values)
    if (v < count) ++counts[v];
  for (size_t v = 1; v < counts.size(); ++v)
    if (counts[v] > counts[ground]) ground = v;
  for (int v = 0; v < count; ++v) {
    ValueMeasure vm;
    vm.value = static_cast<uint32_t>(v);
    vm.count = counts[static_cast<size_t>(v)];
    vm.share = pixels > 0 ? static_cast<double>(vm.count) / pixels : 0;
    vm.most_common = static_cast<size_t>(v) == ground;
    std::vector<bool> inside(grid.values.size());
    for (size_t i = 0; i < grid.values.size(); ++i) inside[i] = grid.values[i] == v;
    vm.lacunarity = lacunarity(grid.width, grid.height, inside, m.lacunarity_box);
    if (!vm.most_common) {
      vm.counts = count_boxes(grid.width, grid.height, inside, base, vm.sizes);
      // fit_box_dimension takes the coarsest boxes first, one level per factor of the base.
      vm.fit = fit_box_dimension(std::vector<uint64_t>(vm.counts.rbegin(), vm.counts.rend()), base);
    }
    m.values.push_back(std::move(vm));
  }
  return m;
}

}  // namespace curdle
