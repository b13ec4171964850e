// The marks round an installer's sheet's frame that a layer sets out from: row (course) and
// column numbers; and on a coursed sheet the gauge rod right of the frame and a chain of
// dimensions under the column numbers (gauge.h), in the strips installer_viewport leaves.
#pragma once

#include <cairo.h>

#include <array>

#include "export/drawing/sheet_drawing.h"
#include "layout/installer_sheets.h"
#include "layout/piece.h"

namespace curdle::sheet_drawing {

// Row numbers on the left, column numbers along the bottom (under the frame of `viewport`),
// where their rows show.
void draw_course_numbers(cairo_t* cr, const InstallerPlan& plan, const LayingExtents& extents,
                         const View& v);

// Right of the window (in the frame's strip when the window fills it): a rod with a tick at each
// course's bed and its height in mm, and the storey levels (layout.storey) drawn longer, across the
// frame too, with their names.
void draw_gauge_rod(cairo_t* cr, const Layout& layout, const LayingExtents& extents, const View& v,
                    const std::array<double, 2>& viewport);

// Under the column numbers: the window's laid width in a chain of dimensions stopping at every
// opening's jamb, each length in mm, and where the chain starts from the datum.
void draw_dimension_chain(cairo_t* cr, const Layout& layout, const View& v,
                          const std::array<double, 2>& viewport);

}  // namespace curdle::sheet_drawing
