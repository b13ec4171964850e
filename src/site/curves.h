// Curves a drawing holds that are neither lines nor circular arcs: ellipses and splines, turned
// into chords that stray at most a tolerance from them (by halving each chord until its middle
// lies close enough, as CAD programs flatten them for display). B-splines are evaluated by
// de Boor's algorithm (Piegl and Tiller, "The NURBS Book", 2nd ed., algorithm A4.1), rational
// when weights are given.
#pragma once

#include <array>
#include <functional>
#include <vector>

namespace curdle::site {

using Point = std::array<double, 2>;

// Points of f over [t0, t1], ends included, each chord within `tolerance` of the curve at its
// middle; at most `most` points (a tolerance that would need more is loosened).
std::vector<Point> flatten_curve(const std::function<Point(double)>& f, double t0, double t1,
                                 double tolerance, size_t most = 20000);

// An ellipse: centre, the end of its major axis from the centre, the minor to major ratio, and
// the parameters (radians) it runs between, counter-clockwise.
std::vector<Point> flatten_ellipse(Point centre, Point major, double ratio, double from, double to,
                                   double tolerance);

// A B-spline of `degree` over `knots` with `control` points and `weights` (empty: all 1).
// Empty when the knots do not fit the points (knots = points + degree + 1).
std::vector<Point> flatten_spline(int degree, const std::vector<double>& knots,
                                  const std::vector<Point>& control,
                                  const std::vector<double>& weights, double tolerance);

}  // namespace curdle::site
