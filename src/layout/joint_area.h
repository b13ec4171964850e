// The area of the joints a layout lays, apart from its elements.
#pragma once

#include "layout/layout.h"

namespace curdle {

// Area of the joints actually laid: the joint strips inside the floor or wall, less openings.
// Computed from the grid alone, so that elements + joints + openings = floor is a real check.
double joint_area(const Layout& layout);

}  // namespace curdle
