// A SPLINE that a drawing gives by its fit points alone, turned into the cubic B-spline CAD
// programs draw through them: global interpolation with the end derivatives as constraints
// (Piegl and Tiller, "The NURBS Book", 2nd ed., section 9.2.2), the parameters the drawing names
// (chord length unless it says otherwise), the "natural" knots, and the end tangents as stored,
// or else estimated from five points. With chord-length parameters each end derivative is as
// long as the fit polygon: this is what AutoCAD and BricsCAD draw, and what ezdxf's
// fit_points_to_cad_cv computes.
#pragma once

#include <optional>
#include <vector>

#include "site/curves.h"

namespace curdle::site {

// How the fit points' parameters are spaced: SPLINE flag 32 (chord length, the default), 64
// (square root of the chord, "centripetal") or 128 (uniform).
enum class KnotSpacing { chord, square_root_chord, uniform };

// The spacing a SPLINE's flags (group 70) name; chord length where they name none.
KnotSpacing knot_spacing_of(long long flags);

struct CubicSpline {
  std::vector<double> knots;
  std::vector<Point> control;
};

// The interpolating cubic B-spline through `fit` (at least two distinct points), with the
// start and end tangents' directions when the drawing stores them (any length; zero: none).
// Each end derivative is as long as the end chord over its parameter step, which for chord
// length is the fit polygon's length. Empty when no spline runs through the points (two of them
// coincide, or fewer than two).
std::optional<CubicSpline> spline_through(const std::vector<Point>& fit,
                                          std::optional<Point> start_tangent,
                                          std::optional<Point> end_tangent,
                                          KnotSpacing spacing = KnotSpacing::chord);

}  // namespace curdle::site
