// layout.svg: the layout in true units (width and height in mm, a viewBox in mm), for print,
// Inkscape and Illustrator.
//
// One group per value (`<g id="value-3" class="value" data-label="red+blue">`). Elements of a
// value that touch are merged into rectangles so that a 1000 x 1000 layout stays small: a
// merged rectangle lists its elements as `data-elements="P-R003-C004:P-R005-C010"` (rows 3 to 5,
// columns 4 to 10), and its fill spans the joints inside it, which the joint lines are drawn
// over. Cut elements are drawn one by one with their element ID as `id`. Then come the joints,
// the openings, the optional stage grid and window, a legend with counts and a title block.
#pragma once

#include <ostream>
#include <string>

#include "curdle/curd.h"
#include "layout/layout.h"
#include "layout/merge_runs.h"

namespace curdle {

void write_layout_svg(std::ostream& out, const Layout& layout);

}  // namespace curdle
