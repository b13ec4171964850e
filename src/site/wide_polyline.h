// A polyline drawn with width (a channel drain, a kerb, a path drawn as one thick line) as the
// area it covers on the plan: each segment a band of its start and end widths, neighbouring
// bands mitred where they turn (bevelled past a sharp turn), the ends cut square, as CAD
// programs draw them. Arcs are taken as chords within the tolerance.
#pragma once

#include <vector>

#include "layout/contour.h"

namespace curdle::site {

struct WideVertex {
  double x = 0, y = 0, bulge = 0;
  double start_width = 0, end_width = 0;  // of the segment that starts here
};

// The closed outline of an open wide polyline, counter-clockwise; empty when it covers no area
// (fewer than two distinct vertices, or no width anywhere).
Contour swept_outline(const std::vector<WideVertex>& vertices, double tolerance);

}  // namespace curdle::site
