#include "site/curves.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace curdle::site {
namespace {

double chord_miss(const std::vector<Point>& p, const std::function<double(const Point&)>& off) {
  double worst = 0;
  for (size_t i = 0; i + 1 < p.size(); ++i)
    worst = std::max(worst, off({(p[i][0] + p[i + 1][0]) / 2, (p[i][1] + p[i + 1][1]) / 2}));
  return worst;
}

TEST(CurvesTest, EllipseChordsStayWithinTheTolerance) {
  // 3 x 1 m, turned 30°, a whole turn.
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const std::vector<Point> p =
      flatten_ellipse({100, 200}, {1500 * c, 1500 * s}, 1.0 / 3, 0, 2 * std::numbers::pi, 0.1);
  ASSERT_GT(p.size(), 16u);
  auto off = [&](const Point& q) {  // how far inside the ellipse, along its normal (near)
    const double x = (q[0] - 100) * c + (q[1] - 200) * s, y = -(q[0] - 100) * s + (q[1] - 200) * c;
    return std::fabs(1 - std::hypot(x / 1500, y / 500)) * 500;
  };
  EXPECT_LE(chord_miss(p, off), 0.1 + 1e-6);
  EXPECT_NEAR(p.front()[0], p.back()[0], 1e-9);
}

TEST(CurvesTest, RationalSplineDrawsAQuarterCircle) {
  // The quarter circle as a rational quadratic B-spline (weights 1, √½, 1).
  const std::vector<Point> control{{1000, 0}, {1000, 1000}, {0, 1000}};
  const std::vector<double> knots{0, 0, 0, 1, 1, 1}, weights{1, std::sqrt(0.5), 1};
  const std::vector<Point> p = flatten_spline(2, knots, control, weights, 0.01);
  ASSERT_GT(p.size(), 4u);
  for (const Point& q : p) EXPECT_NEAR(std::hypot(q[0], q[1]), 1000, 1e-6);
  EXPECT_LE(chord_miss(p, [](const Point& q) { return 1000 - std::hypot(q[0], q[1]); }), 0.01);
}

TEST(CurvesTest, SplinesThatDoNotFitTheirKnotsGiveNothing) {
  const std::vector<Point> control{{0, 0}, {1, 1}, {2, 0}};
  EXPECT_TRUE(flatten_spline(2, {0, 0, 1, 1}, control, {}, 0.1).empty());
  EXPECT_TRUE(flatten_spline(2, {0, 0, 0, 1, 1, 1}, control, {1, -1, 1}, 0.1).empty());
  EXPECT_TRUE(flatten_spline(2, {0, 0, 0, 0, 0, 0}, control, {}, 0.1).empty());
  EXPECT_TRUE(flatten_spline(2, {0, 0, 1, 0, 1, 1}, control, {}, 0.1).empty());
  EXPECT_TRUE(flatten_spline(40, {}, control, {}, 0.1).empty());
}

}  // namespace
}  // namespace curdle::site
