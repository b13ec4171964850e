// Where a surface laid flat lies in a building: its (u, v) along and up its outer face, in
// millimetres, placed by a frame (a straight wall, or an arc for a curved one), as pbrt places
// a shape laid out in its own space. A building is a strip of framed surfaces that share one
// field (src/building); the kinds keep laying flat surfaces, and the 3-D writers and schedules
// map what they laid through the frames.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace curdle {

// One façade: a plan edge from `from` to `to` (straight, or the arc of `bulge`), covering
// [start, start + length) of the strip, its base at `base` mm above the building's datum.
struct SurfaceFrame {
  size_t index = 0;                            // the plan edge from vertex `index` to the next
  std::string name;                            // "S", "NE", ...; "S2" for the second looking south
  std::array<double, 2> from{0, 0}, to{0, 0};  // its ends in plan, mm
  double bulge = 0;                            // the edge's arc (0: straight), as the plan gives it
  double length = 0;                           // along the wall, mm: the chord, or the arc
  double start = 0;                            // where it begins on the unrolled strip, mm
  double base = 0;                             // its v = 0 above the datum, mm
  double height = 0;  // its own height where it is lower than the wall's, mm; 0: the wall's
  double facing = 0;  // the outer face's bearing, degrees clockwise from north
  // The turn from this façade into the next at its end, degrees: positive turns outwards (an
  // outer corner, 90 on a rectangle), negative inwards (an L's bite); 0 where none follows.
  double turn_at_end = 0;
  bool last_of_path = false;  // a free-standing wall's far end: no corner follows
  bool bent = false;  // an arc whose units are bent to it (panels), not straight on its chords
};

// A point of the building, mm: x east, y north, z up from its datum.
using BuildingPoint = std::array<double, 3>;

// The point `inward` mm behind the outer face at strip position (u, v), u within the frame.
BuildingPoint frame_point(const SurfaceFrame& frame, double u, double v, double inward);

// The radius of an arc frame's outer face, mm; 0 for a straight one.
double frame_radius(const SurfaceFrame& frame);

// The radius of the surface `inward` mm behind an arc frame's outer face (smaller where the
// arc bows out, larger where it bows in), mm; 0 for a straight one.
double frame_radius_behind(const SurfaceFrame& frame, double inward);

// The outer face's horizontal direction along the frame at u (unit vector, plan).
std::array<double, 2> frame_direction(const SurfaceFrame& frame, double u);

// The frame that holds strip position u (the last one for u at or past the strip's end); null
// for none.
const SurfaceFrame* frame_at(const std::vector<SurfaceFrame>& frames, double u);

// The strip position u taken round a closed strip of `length` (a unit at the closing corner
// runs past its end), into [0, length).
double wrap_along(double u, double length);

// The parts of [from, to] on each frame, for pieces that turn a corner or a bend: the frame
// and the part's extent along the strip. A range past the strip's end (`length`) goes on from
// its start.
struct FramedSpan {
  const SurfaceFrame* frame = nullptr;
  double from = 0, to = 0;
};
std::vector<FramedSpan> framed_spans(const std::vector<SurfaceFrame>& frames, double length,
                                     double from, double to);

}  // namespace curdle
