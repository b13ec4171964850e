// Parks (Cirovic 2014, figs. 5a and 5b): each curd places one kind of element in its cells —
// a surface (grey paving) or an object (a tree, a bench); cells where no surface survived keep
// the ground (white paving). Elements that share a cell all stay (a + b = ab): surfaces split
// the cell in strips, objects stand in slots along its longer side, clear of each other and of
// the cell's edge by the recipe's clearance.
#pragma once

#include "curdle/curd.h"
#include "layout/layout.h"

namespace curdle {

// Replaces the cells of `layout` by their surfaces and objects.
void plant(Layout& layout, const Design& design, const LayoutSpec& spec);

// The slots objects stand in when `count` share a cell of w x h: inside the clearance, split
// along the longer side.
std::vector<Rect> object_slots(const Rect& cell, size_t count, double clearance);

}  // namespace curdle
