// Unions of round openings, cut as one outline, and of the rectangles of a cut piece: CGAL's
// regularized Boolean operations on circles polygonised within a chord tolerance (CGAL User Manual,
// "2D Regularized Boolean Set-Operations"). CGAL stays inside union.cpp.
#pragma once

#include <vector>

#include "layout/layout.h"

namespace curdle {

// Vertices on the circle such that no chord strays more than `tolerance` inside it.
Ring polygonise(const Circle& circle, double tolerance);

// The union of the circles: one Outline per connected group.
std::vector<Outline> union_of_circles(const std::vector<Circle>& circles, double tolerance);

// The union of axis-aligned rectangles (the pieces of a cut element): one Outline per
// connected part, exact.
std::vector<Outline> union_of_rects(const std::vector<Rect>& rects);

}  // namespace curdle
