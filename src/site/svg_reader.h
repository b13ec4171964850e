// Reads an SVG drawing (Inkscape, Illustrator, a CAD program's SVG export) into a Drawing: the
// XML through libxml2, path data and transforms through SVG++ (its parsers, not ours). Paths
// with lines, circular arcs (kept as arcs), elliptical arcs and Béziers (flattened), <rect>,
// <circle>, <ellipse>, <line>, <polyline>, <polygon> and <use>; each shape's layer is its
// nearest named group (an Inkscape layer's label, else a group's id), else its own id.
// Units come from the root's width and height in mm, cm, in or pt over its viewBox; y is turned
// up, the page's bottom-left corner the drawing's origin.
#pragma once

#include <string>
#include <string_view>

#include "site/drawing.h"

namespace curdle::site {

struct SvgReading {
  double chord_tolerance_mm = 0.05;  // how far flattened curves may stray, mm
  double unit_mm = 0;  // millimetres per user unit when the recipe says (0: from width / viewBox)
};

// Throws InputError naming the file and the element (its id, or its line) for a file that is
// not SVG, holds entity declarations, nests deeper than 64 groups, holds more than kMostShapes
// shapes, or whose path data or transforms do not parse.
Drawing read_svg(std::string_view bytes, const std::string& file_name, const SvgReading& reading);

}  // namespace curdle::site
