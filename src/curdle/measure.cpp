#include "curdle/measure.h"

#include <algorithm>
#include <cmath>

#include "curdle/box_levels.h"
#include "curdle/segment_measures.h"

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
  // Lacunarity as the search measures segments: the picture is a view of `count` values, the
  // values of as many curds as their bits need.
  Design picture;
  picture.lattice = Lattice{base, 2, 1, Mode::canonical};
  while ((1 << picture.curds.size()) < count) picture.curds.emplace_back();
  const Box whole{{0, 0, 0}, {grid.width, grid.height, 1}};
  SegmentMeasures segments;
  segments.reset(picture, whole, grid.values);
  for (int v = 0; v < count; ++v) {
    ValueMeasure vm;
    vm.value = static_cast<uint32_t>(v);
    vm.count = counts[static_cast<size_t>(v)];
    vm.share = pixels > 0 ? static_cast<double>(vm.count) / pixels : 0;
    vm.most_common = static_cast<size_t>(v) == ground;
    // Rows from the bottom: boxes align at the bottom-left corner, as fit and the report count
    // a curd (y up), so that the three give the same counts for one picture.
    std::vector<bool> inside(grid.values.size());
    for (int64_t y = 0; y < grid.height; ++y)
      for (int64_t x = 0; x < grid.width; ++x)
        inside[static_cast<size_t>(y * grid.width + x)] =
            grid.values[static_cast<size_t>((grid.height - 1 - y) * grid.width + x)] == v;
    vm.lacunarity = segments.lacunarity(vm.value, whole, m.lacunarity_box);
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
