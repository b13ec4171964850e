// Boundaries whose edges are straight or circular arcs, as CAD draws them: each vertex carries
// the edge to the next one as a bulge (the DXF convention, AutoCAD DXF Reference, LWPOLYLINE
// group 42): bulge = tan(θ / 4) for the arc's included angle θ, positive counter-clockwise,
// 0 straight. Cutting works on polygons, so a contour is flattened within a chord tolerance;
// drawings, setting-out and areas keep the true arcs.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// One arc edge: its centre and radius, its ends, and its included angle (radians, positive
// counter-clockwise from `from` to `to`).
struct Arc {
  std::array<double, 2> centre{0, 0};
  double radius = 0;
  std::array<double, 2> from{0, 0}, to{0, 0};
  double sweep = 0;
  // The direction of a point of the arc, radians, at `t` from 0 (from) to 1 (to).
  double start_angle() const;
};

// The arc of the edge from a to b (a.bulge != 0).
Arc arc_between(const ContourVertex& a, const ContourVertex& b);
// The bulge of an arc of `sweep` radians (a full turn is not one edge: split it).
double bulge_of_sweep(double sweep);
// A bulge as the readers keep it: 0 where the arc's sagitta is under a billionth of its chord
// (its radius would overflow), else as given.
inline double tidy_bulge(double bulge) { return bulge > -1e-9 && bulge < 1e-9 ? 0 : bulge; }

bool has_arcs(const Contour& contour);
size_t arc_count(const Contour& contour);
// The contour as one rectangle with its edges along x and y (a window), or nullopt.
std::optional<Rect> as_rectangle(const Contour& contour);
// Straight edges between the polygon's vertices.
Contour contour_of(const Polygon& polygon);
// The vertices, with each arc replaced by chords that stray at most `tolerance` from it (the
// chords' ends lie on the arc), at least eight to a full turn.
Polygon flatten(const Contour& contour, double tolerance);
// The enclosed area with the true arcs, mm² (any orientation).
double contour_area(const Contour& contour);
// The contour's extent with the true arcs (an arc's bulge can reach past its ends).
Rect contour_bounds(const Contour& contour);
// The contour moved by (dx, dy) and scaled by `scale` (bulges keep: a similarity keeps arcs).
Contour transformed(const Contour& contour, double scale, double dx, double dy);

}  // namespace curdle
