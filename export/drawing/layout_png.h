// layout.png: the layout drawn at a scale (1 : N) and a resolution (DPI), written through
// OpenImageIO with its resolution recorded, so it prints at size. Edges are antialiased by the
// exact share of each pixel they cover.
#pragma once

#include <filesystem>

#include "io/image.h"
#include "layout/drawing_scale.h"
#include "layout/layout.h"

namespace curdle {

PreviewImage render_layout(const Layout& layout);

// Pixels of the layout's own picture (render_layout), known before it is built.
uint64_t layout_png_pixels(const LayoutSpec& spec, const Box& view);

}  // namespace curdle
