// A building's unit that turns a corner, as one solid: its footprint in plan cut to the
// corner's angle, laid from its course's bed to its top. At an outer corner the stretcher on
// one face and the header on the other meet at the arris and their backs at the mitre; at an
// inner corner the unit showing on one face runs on through the corner, behind the other face,
// to that wall's back. The 3-D writers lay it as one prism instead of a box a face, so that a
// corner at any angle is closed and no unit is counted twice in volume.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "layout/layout.h"

namespace curdle {

struct FramedPrism {
  std::vector<std::array<double, 2>> footprint;  // mm, plan (x east, y north), anticlockwise
  double base = 0, height = 0;                   // mm above the building's datum
};

// The prism of a corner unit (`e.corner` set) laid whole, `depth` mm deep; none for any other
// piece, a corner unit cut by an opening or bent to an arc, or a corner too sharp for the
// unit's reach (each then laid as boxes, framed_boxes.h).
std::optional<FramedPrism> framed_corner(const Layout& layout, const Element& e, double depth);

// The footprint's triangles (indices into it), for a footprint with at most one reflex vertex
// (every corner unit's): a fan from that vertex.
std::vector<std::array<size_t, 3>> footprint_triangles(
    const std::vector<std::array<double, 2>>& footprint);

}  // namespace curdle
