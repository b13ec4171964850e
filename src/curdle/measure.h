// Measuring an existing design, the way Bovill (1996) starts: a picture of a landscape, a
// skyline or a façade quantised to a few values, and for each value its share, its lacunarity
// and its box-counting dimension, so that a new design can share its rhythm.
//
// Boxes of side s = base^j pixels (j = 0, 1, ... while s fits the shorter side) are aligned at
// the picture's bottom-left corner, as `fit` and the report count a curd (y up); a box counts
// when any pixel of the value lies in it (boxes cut by the right or top edge included). The
// dimension is the least-squares slope of log N(s) against log(1/s) (Falconer 2003, sec. 3.1). For
// a Sierpinski carpet 3^k pixels wide measured with base 3, N(3^j) = 8^(k-j) exactly and the slope
// is log 8 / log 3.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "curdle/boxcount.h"

namespace curdle {

// A picture as values, row-major, top row first.
struct ValueGrid {
  int64_t width = 0, height = 0;
  std::vector<uint16_t> values;
};

// Luminance (0 black, 1 white) to `count` values by 1-D k-means (Lloyd), value 0 the lightest;
// `levels` receives each value's mean luminance (to 1/4095). Deterministic: the centres start
// evenly spaced from the lightest pixel to the darkest.
ValueGrid quantise(int64_t width, int64_t height, const std::vector<float>& luminance, int count,
                   std::vector<double>& levels);
// Two values: 1 where the luminance is below `threshold` (the dark figure), 0 elsewhere.
ValueGrid threshold(int64_t width, int64_t height, const std::vector<float>& luminance,
                    double threshold);

struct ValueMeasure {
  uint32_t value = 0;
  uint64_t count = 0;  // pixels
  double share = 0;
  std::optional<double> lacunarity;  // gliding box of the measurement's lacunarity_box, as the
                                     // search measures segments (segment_measures.h)
  bool most_common = false;          // the ground: no dimension is fitted for it
  std::vector<int64_t> sizes;        // box sides, smallest first
  std::vector<uint64_t> counts;      // boxes holding the value, per size
  std::optional<LineFit> fit;        // slope: the box-counting dimension
};

struct Measurement {
  int64_t width = 0, height = 0;
  int base = 2;
  int64_t lacunarity_box = 1;
  std::vector<ValueMeasure> values;
};

// Measures every value 0..count-1 of `grid`. base >= 2.
Measurement measure(const ValueGrid& grid, int count, int base);

// Boxes of side base^j (j = 0.. while the side fits the shorter side) holding a pixel for which
// `inside` is set, smallest boxes first.
std::vector<uint64_t> count_boxes(int64_t width, int64_t height, const std::vector<bool>& inside,
                                  int base, std::vector<int64_t>& sizes);

}  // namespace curdle
