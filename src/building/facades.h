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

namespace curdle {

struct Facade {
  size_t index = 0;                            // the plan edge from vertex `index` to the next
  std::string name;                            // "S", "NE", ...; "S2" for the second looking south
  std::array<double, 2> from{0, 0}, to{0, 0};  // its ends in plan, mm
  double bulge = 0;                            // the edge's arc (0: straight), as the plan gives it
  double length = 0;                           // along the wall, mm: the chord, or the arc
  double start = 0;                            // where it begins on the unrolled strip, mm
  double facing = 0;                // the outer face's bearing, degrees clockwise from north
  bool outer_corner_at_end = true;  // false: the building turns inwards at its end (an L's bite)
};

// The plan's façades from vertex `start`, anticlockwise (a clockwise plan is taken the other
// way round). Throws InputError (key `plan`) for a plan of fewer than three vertices, one that
// crosses itself, an edge shorter than `shortest` mm, or an arc of half a turn or more.
std::vector<Facade> unroll_plan(const Contour& plan, size_t start, double shortest);

// The envelope's length round the building: the strip's, mm.
double strip_length(const std::vector<Facade>& facades);

// The compass point of a bearing, in eight: 0 "N", 45 "NE", ..., 315 "NW".
std::string compass_point(double bearing);

}  // namespace curdle
