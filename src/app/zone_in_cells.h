// Search zones in millimetres: `empty[:CURD]=X,Y,W,H mm` on a recipe with a layout names a
// rectangle of the floor or wall; it becomes the cells of the elements laid there, so that the
// search's zones and the layout's share one frame.
#pragma once

#include <string>

#include "app/run.h"

namespace curdle::app {

// The target with a zone in mm rewritten in cells from the segment's corner (the floor's
// cells); any other target as it is. Throws InputError naming the target and what is allowed.
std::string zone_in_cells(const std::string& target, const Run& run);

}  // namespace curdle::app
