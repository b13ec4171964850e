// layout.png: the layout drawn at a scale (1 : N) and a resolution (DPI), written through
// OpenImageIO with its resolution recorded, so it prints at size. Edges are antialiased by the
// exact share of each pixel they cover.
#pragma once

#include <filesystem>

#include "export/preview_png.h"
#include "layout/layout.h"

namespace curdle {

// 1 : scale; the spec's, or the smallest standard scale (1, 2, 5, 10, 20, 25, 50, 100, ...)
// at which the layout fits the drawing area of its sheet (layout.paper, A3 by default) in
// either orientation: drawing_sheet.h.
double drawing_scale(const Layout& layout);

PreviewImage render_layout(const Layout& layout);

// A layout with only the extent and the spec of the one `spec` makes of `view`: enough to
// pick scales and sheets before it is built.
Layout layout_extent(const LayoutSpec& spec, const Box& view);

// Pixels of the layout's own picture (render_layout), known before it is built.
uint64_t layout_png_pixels(const LayoutSpec& spec, const Box& view);

}  // namespace curdle
