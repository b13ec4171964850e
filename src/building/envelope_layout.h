// An envelope's courses as a layout's elements on its unrolled strip: one element per unit,
// its value taken once from the field cell under the middle of its face (so that a corner
// unit, on two façades, is one piece with one value), cut at the openings; the façades as the
// layout's frames, so that the 3-D writers and schedules place every piece in the building.
#pragma once

#include <cstdint>
#include <vector>

#include "building/building.h"
#include "building/coursing.h"
#include "building/strip_ring.h"

namespace curdle {

// Lays the units of `coursing`, in its bond, on `layout` (the strip's surface and openings,
// builder.h's lay_surface), `values` being the view's cells (x fastest): round a closed
// envelope's `ring` where there is one, else a cell a unit's pitch from the strip's start.
void lay_envelope(Layout& layout, const Envelope& env, const Coursing& coursing,
                  const std::vector<uint16_t>& values, const LayoutSpec& spec,
                  const std::optional<StripRing>& ring = std::nullopt);

// How corners and the closing seam fall against the stage grid, for the report: each corner's
// place in the cells of every stage.
std::vector<std::string> corner_grid_notes(const Layout& layout, const Design& design,
                                           const std::optional<StripRing>& ring = std::nullopt);

}  // namespace curdle
