// Sheet 1's setting-out plan of a building's curved façades: the walls in plan at a standard
// scale, north up, each arc's chord with the offsets to the arc at its stations, the ends by
// their coordinates and the way to the centre, with the lines that give the centre, radius,
// sweep and how the units sit on the arc (curved_facade.h).
#pragma once

#include <cairo.h>

#include "layout/layout.h"

namespace curdle::sheet_drawing {

// Draws the plan in the box at (x, y), `w` x `h` mm on paper; false (nothing drawn) where the
// layout has no curved façade or the box holds no useful plan.
bool draw_setting_out_plan(cairo_t* cr, const Layout& layout, double x, double y, double w,
                           double h);

}  // namespace curdle::sheet_drawing
