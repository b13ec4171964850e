// A picture read as the cells of a curd field, for fitting: pixels grouped into the k x k cells
// a preview draws them as (found, or named), and each cell's value, whose bits are the curds,
// told apart by the picture's own flat colours when it has them (a preview: red, blue and their
// purple are one grey) and by luminance otherwise.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/image.h"

namespace curdle::app {

struct PictureCells {
  int64_t width = 0, height = 0;  // in cells
  int pixels_per_cell = 1;
  std::vector<uint16_t> values;           // row-major, top row first; value 0 the ground
  std::vector<std::string> curd_colours;  // "#rrggbb" per curd: its colour, or its grey
  bool by_colour = false;                 // values told apart by the picture's colours
};

// `cell_pixels`: 0 finds it (the largest k dividing both sides whose every k x k block is one
// shade; 1 when none), else the pixels a cell is a side. InputError when the picture's sides are
// not whole cells of it.
PictureCells picture_cells(const LuminanceImage& image, int curds, int cell_pixels);

// The picture as `tones` tones, 0 the lightest (a Markov curd's dead ground) and then then darker
// and darker: its own flat colours when it has no more than `tones` of them, else
// its luminance quantised (measure.h). curd_colours holds each tone's colour, 0 first.
PictureCells picture_tones(const LuminanceImage& image, int tones, int cell_pixels);

}  // namespace curdle::app
