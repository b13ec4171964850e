// layout.dxf: every layout kind as a CAD drawing (dxf_document.h): the surface's outline, its
// openings, each piece as laid as a closed polyline (a circle for round openings and
// canopies) on its material's layer, and each piece's ID, the same as in every other file, on
// layer ID, which does not plot; a perforation's fabrication sheets by their IDs on layer SHEETS
// (not plotted). Millimetres from the layout's bottom-left corner; blocks as
// their plan, one layer per level and material. `in_site_drawing`: in the coordinates and units
// of the DXF the surface was read from instead (layout.site_frame), to overlay it.
#pragma once

#include <filesystem>

#include "layout/layout.h"

namespace curdle {

void write_layout_dxf(const std::filesystem::path& path, const Layout& layout,
                      bool in_site_drawing);

}  // namespace curdle
