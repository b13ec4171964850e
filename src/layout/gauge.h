// What a bricklayer sets out from on a coursed sheet, beside the courses' numbers: a gauge rod
// (the bed of each course, mm above the datum, and the storey levels) and a chain of dimensions
// along the sheet (its edges and the openings' jambs), for one sheet's window.
#pragma once

#include <string>
#include <vector>

#include "layout/layout.h"
#include "layout/piece.h"

namespace curdle {

struct GaugeMark {
  double at = 0;      // height above the datum, mm
  std::string label;  // "1125", or "level 2 +6450"
  bool level = false;
};

// The bed of every course whose bed lies in the window (from `extents`), the wall's top, and
// every storey level (layout.drawing.storey apart, from the datum) up to the wall's top; by
// height, a level before a course at the same height.
std::vector<GaugeMark> gauge_marks(const Layout& layout, const LayingExtents& extents,
                                   const Rect& window);

// Where a chain of dimensions along the window stops, mm from the datum, left to right: the
// laid surface's part of the window, and the jambs of the openings (the surface's own, not
// excluded zones) in it.
std::vector<double> dimension_stops(const Layout& layout, const Rect& window);

}  // namespace curdle
