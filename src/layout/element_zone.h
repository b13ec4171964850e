// Which of a layout's zones ([[layout.zones]]) an element lies in, as the schedules book it: a
// standing object (a tree, a bench) where it stands, a laid piece where most of its area lies.
#pragma once

#include <string>

#include "layout/layout.h"

namespace curdle {

// The first zone holding the point (x, y), mm; "" for none.
std::string zone_at(const Layout& layout, double x, double y);

// A standing object's zone: the one holding its centre. A laid piece's: the one holding the
// largest share of its area, or none when more of it lies outside every zone (a piece cut round
// an excluded zone lies in none of it, wherever the centre of its box falls).
std::string zone_of_element(const Layout& layout, const Element& e);

}  // namespace curdle
