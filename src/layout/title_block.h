// The words a drawing of a layout carries: the title block's lines (recipe, seed and lattice,
// probabilities, the surface and its elements, origin or sheet facts, units) and the legend's
// unit, so that layout.svg, layout.png and layout.pdf say the same.
#pragma once

#include <string>
#include <vector>

#include "layout/drawing_sheet.h"
#include "layout/layout.h"

namespace curdle {

std::vector<std::string> title_lines(const Layout& layout);

// A point of the layout (mm from its datum) in the site drawing's coordinates, at the drawing's
// precision with thousands grouped: "E 530,012.500 N 180,004.000 m in site.dxf".
std::string site_point_text(const SiteFrame& frame, double x_mm, double y_mm);

// "window 48,24,67,67 of the 512 x 512 field" when the layout lays a segment of its design's
// field (the seed line says so); empty when it lays the whole field.
std::string segment_text(const Layout& layout);

// What a legend entry counts: "tile", "panel", "cell" (perforation, park), "bay", "voxel".
std::string legend_unit(const Layout& layout);

// "12 tiles", "1 cell".
std::string legend_count(const Layout& layout, uint64_t count);

}  // namespace curdle
