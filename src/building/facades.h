// A building's envelope as façades: its plan (a closed contour, straight edges and arcs, in mm)
// unrolled into one strip from a start corner, anticlockwise, so that one curd field can run
// round every corner (issue: whole buildings). Each façade is one plan edge: where it lies in
// plan, how long it is along the wall (an arc's length for a curved wall), where it starts on
// the strip, and its name, the compass point its outer face looks to (plan +y is north).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "layout/layout.h"
#include "layout/surface_frame.h"

namespace curdle {

// A façade is a framed surface of the strip (layout/surface_frame.h).
using Facade = SurfaceFrame;

// The plan's façades from vertex `start`, anticlockwise (a clockwise plan is taken the other
// way round). Throws InputError (key `plan`) for a plan of fewer than three vertices, one that
// crosses itself, an edge shorter than `shortest` mm, or an arc of half a turn or more.
std::vector<Facade> unroll_plan(const Contour& plan, size_t start, double shortest);

// A free-standing wall along an open `path` (two or more vertices, straight edges or arcs): its
// faces from the first vertex, the outer face on the right of the path, the last one's end
// stopped. Throws InputError (key `path`) as unroll_plan does.
std::vector<Facade> unroll_path(const Contour& path, double shortest);

// The envelope's length round the building: the strip's, mm.
double strip_length(const std::vector<Facade>& facades);

// The compass point of a bearing, in eight: 0 "N", 45 "NE", ..., 315 "NW".
std::string compass_point(double bearing);

}  // namespace curdle
