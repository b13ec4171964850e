// A SPLINE that a drawing gives by its fit points alone, turned into the cubic B-spline CAD
// programs draw through them: global interpolation with the end derivatives as constraints
// (Piegl and Tiller, "The NURBS Book", 2nd ed., section 9.2.2), chord-length parameters, the
// "natural" knots, and the end tangents as stored, or else estimated from five points, each
// scaled to the fit polygon's length. This is what AutoCAD and BricsCAD draw, and what ezdxf's
// fit_points_to_cad_cv computes.
#pragma once

#include <optional>
#include <vector>

#include "site/curves.h"

namespace curdle::site {

struct CubicSpline {
  std::vector<double> knots;
  std::vector<Point> control;
};

// The interpolating cubic B-spline through `fit` (at least two distinct points), with the
// start and end tangents' directions when the drawing stores them (any length; zero: none).
// Empty when no spline runs through the points (two of them coincide, or fewer than two).
std::optional<CubicSpline> spline_through(const std::vector<Point>& fit,
                                          std::optional<Point> start_tangent,
                                          std::optional<Point> end_tangent);

}  // namespace curdle::site
