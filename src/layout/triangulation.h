// Triangulating a polygon with holes: a constrained Delaunay triangulation of all its rings,
// keeping the faces inside an odd number of rings (CGAL, "2D Triangulation", constrained
// triangulations and the nesting levels of polygon domains). CGAL stays inside the .cpp.
#pragma once

#include <array>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// Triangles of the region inside `rings` (outer boundary and holes, in any orientation),
// each counter-clockwise, as corner coordinates.
std::vector<std::array<std::array<double, 2>, 3>> triangulate(const std::vector<Ring>& rings);

}  // namespace curdle
