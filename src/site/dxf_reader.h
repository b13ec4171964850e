// Reads an ASCII DXF (AutoCAD R12 to 2018) into a Drawing: LWPOLYLINE and POLYLINE (bulges as
// arcs; drawn with width, also the strip they cover), LINE, ARC, CIRCLE, ELLIPSE and SPLINE
// (flattened; a spline given by fit points drawn through them as CAD draws it), HATCH boundary
// paths, and INSERTs of blocks (placed with their base point, scale, rotation and arrays,
// nested). Mirrored entities (extrusion 0, 0, -1) are turned back into the plan; anything off
// the plan's plane is refused.
#pragma once

#include <string>
#include <string_view>

#include "site/drawing.h"

namespace curdle::site {

struct DxfReading {
  // How far flattened ellipses and splines may stray, mm.
  double chord_tolerance_mm = 0.05;
  // Millimetres per unit when the recipe says (0: as $INSUNITS says).
  double unit_mm = 0;
};

// Throws InputError naming the file (and the entity's handle) for a file that is not an ASCII
// DXF (binary DXF and DWG are named as such), is larger than kMostDrawingBytes, or holds more
// than kMostShapes entities once its blocks are placed.
Drawing read_dxf(std::string_view bytes, const std::string& file_name, const DxfReading& reading);

// Millimetres per unit for a $INSUNITS code, or 0 for unitless and units that no site is drawn in.
double insunits_mm(int code);

}  // namespace curdle::site
