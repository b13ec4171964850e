// How an element's body stands in 3-D, as the glb and the IFC both build it: a laid piece the
// surface's thickness, a block its storey, a park's tree a trunk with its canopy above (as tall
// as wide), a bench or other standing object a block of kStandingHeight.
#pragma once

#include "layout/layout.h"

namespace curdle {

inline constexpr double kTrunkWidth = 200;      // mm, a tree's trunk across
inline constexpr double kTrunkHeight = 2200;    // mm, to where its canopy starts
inline constexpr double kStandingHeight = 450;  // mm, a bench's and other standing objects'

// How tall the body stands above what it stands on, mm.
double body_height(const Layout& layout, const Element& e);

// A tree's trunk and canopy, m³; -1 for a body that is a prism of the element's area.
double body_volume(const Element& e);

}  // namespace curdle
