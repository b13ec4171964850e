// The part of a large polygon near one piece: a surveyed outline of 10,000 corners made every
// piece cut along it an exact Boolean operation over all of them (45 s for 360 pieces). Clipped
// to a box around the piece first, the operation sees only the few corners that matter.
#pragma once

#include <optional>

#include "layout/layout.h"
#include "layout/zone.h"

namespace curdle {

// The simple polygon's part within the box, by Sutherland and Hodgman's reentrant clipping
// ("Reentrant polygon clipping", CACM 17(1), 1974), which is exact as a point set where the
// part is one piece: when the polygon's boundary enters the box at most once. Empty when they
// do not meet; the box's corners when it lies inside the polygon; nullopt when the part may
// fall in several pieces (or touches the box's side), where the caller uses the whole polygon.
std::optional<Polygon> clip_to_box(const Polygon& polygon, const Rect& box);

// The same, to the bit, for a polygon with an index of its edges: the edges far from the box,
// which the count of its corners inside and of entries never counts, are not looked at.
std::optional<Polygon> clip_to_box(const PolygonIndex& index, const Rect& box);

}  // namespace curdle
