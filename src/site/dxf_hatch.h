// A HATCH's boundary paths (DXF Reference, "Boundary Path Data"): polylines with bulges, or
// edges in order (lines, circular and elliptic arcs, splines), each path a closed contour in the
// hatch's object coordinate system.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "layout/contour.h"
#include "site/dxf_groups.h"

namespace curdle::site {

struct HatchBoundaries {
  std::vector<Contour> loops;
  size_t flattened = 0;  // curved edges taken as chords
};

// The paths of the HATCH whose groups these are (nullopt: it gives none), curved edges within
// `tolerance` (drawing units); `numbers` reads its values strictly. InputError naming `name`
// ("HATCH 60") and `layer` for a path that lacks a group or has an edge of no known type.
std::optional<HatchBoundaries> hatch_boundaries(const std::vector<DxfGroup>& groups,
                                                const DxfGroups& numbers, const std::string& name,
                                                const std::string& layer, double tolerance);

}  // namespace curdle::site
