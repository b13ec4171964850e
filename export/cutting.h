// Cutting files for each fabrication sheet of a perforated surface:
//   DXF (AutoCAD 2007, millimetres, through dxf_document.h): the sheet outline, the openings as
//     circles on one layer per diameter (HOLE_D16, HOLE_D22_6), merged openings as closed
//     polylines (OPENING_OUTLINE), each opening's element ID as text on layer ID (does not
//     plot), and the sheet ID on layer TEXT; millimetres from the sheet's bottom-left corner
//     (the cutter's origin), and for a surface read from a site drawing where that corner lies
//     in the drawing's coordinates, on layer ID;
//   SVG for laser cutters: the same, in true millimetres, hairline strokes, no fill.
#pragma once

#include <filesystem>
#include <ostream>

#include "layout/layout.h"

namespace curdle {

void write_sheet_dxf(const std::filesystem::path& path, const Layout& layout, int sheet);
void write_sheet_svg(std::ostream& out, const Layout& layout, int sheet);

}  // namespace curdle
