// Perforated sheets (Cirovic 2014, fig. 4): each curd is a round opening at an offset from the
// cell centre. Openings that overlap in a cell either become one larger opening of their summed
// area (mix, a + b = c) or are cut as their union (keep, a + b = ab). Then the fabrication rules:
// smallest diameter, least bridge between openings and to the sheet edge — reported, and fixed
// by dropping openings when the recipe asks.
#pragma once

#include "curdle/curd.h"
#include "layout/layout.h"

namespace curdle {

// Replaces the cells of `layout` (laid as elements on the sheet) by their openings.
void perforate(Layout& layout, const Design& design, const LayoutSpec& spec);

// The least material between two openings made of these circles (negative when they overlap).
double bridge(const std::vector<Circle>& a, const std::vector<Circle>& b);

}  // namespace curdle
