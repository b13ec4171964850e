// Cutting files for each fabrication sheet of a perforated surface:
//   DXF (AutoCAD 2007, millimetres, through dxf_document.h): the sheet outline, the openings as
//     circles on one layer per diameter (HOLE_D16, HOLE_D22_6), merged openings as closed
//     polylines (OPENING_OUTLINE), each opening's element ID as text on layer ID (does not
//     plot), and the sheet ID on layer TEXT; millimetres from the sheet's bottom-left corner
//     (the cutter's origin), and for a surface read from a site drawing where that corner lies
//     in the drawing's coordinates, on layer ID;
//   SVG for laser cutters: the same, in true millimetres, hairline strokes, no fill.
// A sheet rolled to an arc (a screen on a curved façade) is cut as its developed blank: lengths
// along the arc taken at mid-thickness, and a line that says how it is rolled.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>

#include "layout/layout.h"

namespace curdle {

// What the roller needs of a sheet rolled to an arc: its blank, its inside radius and its
// length along the outer face.
std::string rolled_text(const FabricationSheet& sheet, double thickness);

void write_sheet_dxf(const std::filesystem::path& path, const Layout& layout, int sheet);
void write_sheet_svg(std::ostream& out, const Layout& layout, int sheet);

}  // namespace curdle
