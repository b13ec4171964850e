// A free curve of an outline or a zone (a spline or an ellipse read from a drawing, or a curve
// given as many short chords): it has no centre to set out from, so it is set out as a setter-out
// sets out such a curve, by offsets at regular stations, not by a tick at every chord's corner.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "layout/layout.h"

namespace curdle {

struct CurveStations {
  size_t first = 0, last = 0;  // the run's vertices in the contour, first to last (cyclic)
  bool along_x = true;         // stations along x, offsets in y; else along y, offsets in x
  double step = 0;             // between stations, mm: a round number
  // Each station's point on the curve (x, y); the run's two ends are corners set out as such.
  std::vector<std::array<double, 2>> points;
};

// The free curves of a closed contour: runs of at least four straight edges, none along x or y,
// each turning from the one before by under 30 degrees (arcs have centres: they are set out by
// arc_setting_out.h). Stations every `step` of 100, 200, 250 or 500 mm times a power of ten,
// the finest giving at most 12 along the run's longer extent.
std::vector<CurveStations> curve_stations(const Contour& contour);

// Whether vertex i of a contour of n vertices lies strictly inside one of the runs (their ends
// stay corners).
bool inside_a_curve(const std::vector<CurveStations>& curves, size_t i, size_t n);

}  // namespace curdle
