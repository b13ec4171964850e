#include "site/spline_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace curdle::site {
namespace {

const std::vector<Point> kFit = {{0, 0}, {4, 8}, {1, 16}, {6, 24}, {0, 30}};

// The control points and knots ezdxf 0.18's fit_points_to_cad_cv gives for the same fit
// points (its default five-point tangents), which match what BricsCAD and AutoCAD draw.
TEST(SplineFitTest, EstimatedTangentsGiveWhatCadDraws) {
  const auto s = spline_through(kFit, std::nullopt, std::nullopt);
  ASSERT_TRUE(s);
  const std::vector<double> knots = {0, 0, 0, 0, 0.252609257079, 0.493913911086, 0.760353816876,
                                     1, 1, 1, 1};
  const std::vector<Point> control = {{0, 0},
                                      {2.039118476, 2.175059707},
                                      {6.703815491, 7.915938644},
                                      {-2.656237129, 16.475132984},
                                      {9.955203461, 23.635867833},
                                      {2.593865822, 28.872232251},
                                      {0, 30}};
  ASSERT_EQ(s->knots.size(), knots.size());
  for (size_t i = 0; i < knots.size(); ++i) EXPECT_NEAR(s->knots[i], knots[i], 1e-9) << i;
  ASSERT_EQ(s->control.size(), control.size());
  for (size_t i = 0; i < control.size(); ++i) {
    EXPECT_NEAR(s->control[i][0], control[i][0], 1e-8) << i;
    EXPECT_NEAR(s->control[i][1], control[i][1], 1e-8) << i;
  }
}

// The same fit points under the other spacings a SPLINE's flags name, against ezdxf 0.18's
// global_bspline_interpolation with the same parameters and end derivatives (each the end
// chord over its parameter step).
TEST(SplineFitTest, SquareRootChordAndUniformSpacingsAsTheFlagsSay) {
  EXPECT_EQ(knot_spacing_of(8), KnotSpacing::chord);
  EXPECT_EQ(knot_spacing_of(8 | 32 | 1024), KnotSpacing::chord);
  EXPECT_EQ(knot_spacing_of(8 | 64 | 1024), KnotSpacing::square_root_chord);
  EXPECT_EQ(knot_spacing_of(8 | 128 | 1024), KnotSpacing::uniform);
  struct Expected {
    KnotSpacing spacing;
    std::vector<double> inner_knots;
    std::vector<Point> control;
  };
  const std::vector<Expected> cases = {{KnotSpacing::square_root_chord,
                                        {0.251358418579, 0.497028151462, 0.755175958608},
                                        {{0, 0},
                                         {2.039118476, 2.175059707},
                                         {6.724302104, 8.07940648},
                                         {-2.66011224, 16.177170914},
                                         {9.941415392, 23.933837673},
                                         {2.593865822, 28.872232251},
                                         {0, 30}}},
                                       {KnotSpacing::uniform,
                                        {0.25, 0.5, 0.75},
                                        {{0, 0},
                                         {2.039118476, 2.175059707},
                                         {6.746342643, 8.244713984},
                                         {-2.670876963, 15.880911495},
                                         {9.937165208, 24.231640037},
                                         {2.593865822, 28.872232251},
                                         {0, 30}}}};
  for (const Expected& e : cases) {
    const auto s = spline_through(kFit, std::nullopt, std::nullopt, e.spacing);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->knots.size(), 11u);
    for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(s->knots[4 + i], e.inner_knots[i], 1e-9) << i;
    ASSERT_EQ(s->control.size(), e.control.size());
    for (size_t i = 0; i < e.control.size(); ++i) {
      EXPECT_NEAR(s->control[i][0], e.control[i][0], 1e-8) << i;
      EXPECT_NEAR(s->control[i][1], e.control[i][1], 1e-8) << i;
    }
  }
}

TEST(SplineFitTest, StoredTangentsAreHonoured) {
  // Unit directions, scaled to the fit polygon's length as CAD scales them.
  const auto s = spline_through(kFit, Point{1, 0}, Point{0, 1});
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->control[1][0], 2.98142397, 1e-8);
  EXPECT_NEAR(s->control[1][1], 0, 1e-12);
  EXPECT_NEAR(s->control[3][0], -2.872856348, 1e-8);
  EXPECT_NEAR(s->control[5][1], 27.171572875, 1e-8);
}

TEST(SplineFitTest, TheCurveRunsThroughEveryFitPoint) {
  const auto s = spline_through(kFit, std::nullopt, std::nullopt);
  ASSERT_TRUE(s);
  const std::vector<Point> drawn = flatten_spline(3, s->knots, s->control, {}, 1e-6);
  for (const Point& f : kFit) {
    double nearest = 1e300;
    for (size_t i = 1; i < drawn.size(); ++i) {
      const Point a = drawn[i - 1], b = drawn[i];
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      const double t =
          std::clamp(((f[0] - a[0]) * dx + (f[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      nearest = std::min(nearest, std::hypot(a[0] + t * dx - f[0], a[1] + t * dy - f[1]));
    }
    EXPECT_LT(nearest, 1e-5) << f[0] << ", " << f[1];
  }
}

TEST(SplineFitTest, TwoPointsAreAStraightLineAndOneIsNothing) {
  const auto s = spline_through({{0, 0}, {10, 0}, {10, 0}}, std::nullopt, std::nullopt);
  ASSERT_TRUE(s);
  for (const Point& c : s->control) EXPECT_NEAR(c[1], 0, 1e-12);
  EXPECT_FALSE(spline_through({{3, 3}, {3, 3}}, std::nullopt, std::nullopt));
  EXPECT_FALSE(spline_through({{0, 0}, {1e308, 0}, {-1e308, 0}}, std::nullopt, std::nullopt));
}

}  // namespace
}  // namespace curdle::site
