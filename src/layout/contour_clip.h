// A contour with arcs clipped to a box, its arcs kept as arcs: a fabrication sheet cut from an
// outline with an arched edge is drawn for the cutter with the sheet's part of the true arc.
#pragma once

#include <optional>

#include "layout/contour.h"

namespace curdle {

// The contour's part within the box, each arc that crosses a side split there into the arcs
// inside it (Sutherland and Hodgman's reentrant clipping, side by side, with the arc's crossings
// of each side found on its circle). Exact where the part is one piece (box_clip.h says when);
// nullopt otherwise, where the caller keeps the chords. Empty when they do not meet.
std::optional<Contour> clip_contour_to_box(const Contour& contour, const Rect& box,
                                           double tolerance);

}  // namespace curdle
