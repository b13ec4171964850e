// Cut pieces too narrow to lay: every edge a piece is cut along counts, the surface's edges and
// its openings (layout.min_cut), and the grid can be moved to avoid them (layout.shift).
#pragma once

#include <array>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// The narrowest run of a piece across x (along_x: the shortest horizontal stretch of material
// at any height) or across y. A rectangle's is its width or height; an L-shaped panel's is its
// thinner leg, however its rectangles happen to be split.
double narrowest_run(const std::vector<Rect>& pieces, bool along_x);

// The narrowest cut piece allowed across x (axis 0) or y (1): layout.min_cut's, or a third of
// the element that way when it is not given (a 65 mm brick course under 21.7 mm is refused).
double least_cut(const LayoutSpec& spec, int axis);

// Tile, paving and facade layouts: every cut piece narrower than the least cut goes to the
// violations, with where it was cut (an edge or an opening); a note gives how many, the
// layout.shift that leaves fewer when laying the surface with it (over `openings`) shows that
// it does, and the sizes and counts of the specials or closers that no shift clears.
void check_cut_widths(Layout& layout, const LayoutSpec& spec, const std::vector<Rect>& openings);

// The shift along x (axis 0) or y (1) that leaves the fewest slivers, and how many it leaves
// and the current shift leaves, counted row by row (or column by column) across the surface
// less its openings.
struct ShiftAdvice {
  double shift = 0;
  uint64_t slivers = 0, now = 0;    // below the rule with the advised shift, and now
  uint64_t cuts = 0, cuts_now = 0;  // cut pieces of any width, the same
};
ShiftAdvice best_shift(const Layout& layout, const LayoutSpec& spec, int axis);

// Facade: the share of the wall its openings (the first `openings` of layout.openings; excluded
// zones follow them) take, as layout.open_area and a note.
void report_open_area(Layout& layout, size_t openings);

}  // namespace curdle
