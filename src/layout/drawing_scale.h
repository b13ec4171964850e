// The scale a layout is drawn at on its sheet, known before any drawing is made: what layout.png,
// the drawing set and the size guards all read.
#pragma once

#include "curdle/box.h"
#include "layout/layout.h"

namespace curdle {

// 1 : scale; the spec's, or the smallest standard scale (1, 2, 5, 10, 20, 25, 50, 100, ...)
// at which the layout fits the drawing area of its sheet (layout.paper, A3 by default) in
// either orientation: drawing_sheet.h.
double drawing_scale(const Layout& layout);

// A layout with only the extent and the spec of the one `spec` makes of `view`: enough to
// pick scales and sheets before it is built.
Layout layout_extent(const LayoutSpec& spec, const Box& view);

}  // namespace curdle
