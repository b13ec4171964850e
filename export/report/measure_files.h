// A measured picture's files: measure.json (per value its level, count, share, lacunarity and
// box counts with the fitted dimension) and measure.png, the log-log plot of the box counts.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "curdle/measure.h"
#include "io/image.h"

namespace curdle {

struct MeasuredPicture {
  std::string source;  // the picture's file name
  Measurement measurement;
  std::vector<double> levels;  // each value's mean luminance, 0 black to 1 white
};

// The value's grey as "#rrggbb", from its mean luminance.
std::string level_colour(double luminance);

nlohmann::ordered_json measure_to_json(const MeasuredPicture& picture);

// log N(s) against log(1/s) for every fitted value: its boxes as dots, its fit as a line, each
// value in a colour of its own (listed in measure.json as plot_colour), on a grid of the
// powers of the base.
PreviewImage plot_box_counts(const MeasuredPicture& picture);
// The plot colour of the n-th fitted series.
std::string series_colour(size_t n);

}  // namespace curdle
