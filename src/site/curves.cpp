#include "site/curves.h"

#include <algorithm>
#include <cmath>

namespace curdle::site {
namespace {

double distance_to_chord(const Point& p, const Point& a, const Point& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length = std::hypot(dx, dy);
  if (length == 0) return std::hypot(p[0] - a[0], p[1] - a[1]);
  return std::fabs((p[0] - a[0]) * dy - (p[1] - a[1]) * dx) / length;
}

}  // namespace

std::vector<Point> flatten_curve(const std::function<Point(double)>& f, double t0, double t1,
                                 double tolerance, size_t most) {
  // Sixteen first chords, so that an S-bend whose middle lies on its chord is still seen.
  constexpr int kFirst = 16;
  std::vector<Point> points{f(t0)};
  struct Span {
    double a, b;
    Point pa, pb;
    int depth;
  };
  std::vector<Span> stack;
  for (int k = kFirst; k > 0; --k) {
    const double a = t0 + (t1 - t0) * (k - 1) / kFirst, b = t0 + (t1 - t0) * k / kFirst;
    stack.push_back({a, b, f(a), f(b), 0});
  }
  const int deepest =
      static_cast<int>(std::log2(static_cast<double>(std::max<size_t>(most, 32)) / kFirst));
  while (!stack.empty()) {
    const Span s = stack.back();
    stack.pop_back();
    const double m = (s.a + s.b) / 2;
    const Point pm = f(m);
    if (s.depth < deepest && distance_to_chord(pm, s.pa, s.pb) > tolerance) {
      stack.push_back({m, s.b, pm, s.pb, s.depth + 1});
      stack.push_back({s.a, m, s.pa, pm, s.depth + 1});
      continue;
    }
    points.push_back(s.pb);
  }
  return points;
}

std::vector<Point> flatten_ellipse(Point centre, Point major, double ratio, double from, double to,
                                   double tolerance) {
  const Point minor{-major[1] * ratio, major[0] * ratio};
  while (to <= from) to += 2 * M_PI;
  return flatten_curve(
      [&](double t) {
        return Point{centre[0] + major[0] * std::cos(t) + minor[0] * std::sin(t),
                     centre[1] + major[1] * std::cos(t) + minor[1] * std::sin(t)};
      },
      from, to, tolerance);
}

std::vector<Point> flatten_spline(int degree, const std::vector<double>& knots,
                                  const std::vector<Point>& control,
                                  const std::vector<double>& weights, double tolerance) {
  const size_t n = control.size();
  const auto p = static_cast<size_t>(degree);
  if (degree < 1 || degree > 10 || n <= p || knots.size() != n + p + 1) return {};
  if (!weights.empty() && weights.size() != n) return {};
  for (size_t i = 1; i < knots.size(); ++i)
    if (!(knots[i] >= knots[i - 1])) return {};
  for (double w : weights)
    if (!(w > 0) || !std::isfinite(w)) return {};
  const double lo = knots[p], hi = knots[n];
  if (!(hi > lo)) return {};
  auto at = [&](double t) {
    // The knot span holding t, then de Boor's triangle in homogeneous coordinates.
    size_t k = p;
    while (k + 1 < n && t >= knots[k + 1]) ++k;
    std::vector<std::array<double, 3>> d(p + 1);
    for (size_t j = 0; j <= p; ++j) {
      const size_t i = k - p + j;
      const double w = weights.empty() ? 1 : weights[i];
      d[j] = {control[i][0] * w, control[i][1] * w, w};
    }
    for (size_t r = 1; r <= p; ++r)
      for (size_t j = p; j >= r; --j) {
        const size_t i = k - p + j;
        const double span = knots[i + p + 1 - r] - knots[i];
        const double a = span > 0 ? (t - knots[i]) / span : 0;
        for (int c = 0; c < 3; ++c) d[j][c] = (1 - a) * d[j - 1][c] + a * d[j][c];
      }
    return Point{d[p][0] / d[p][2], d[p][1] / d[p][2]};
  };
  return flatten_curve(at, lo, hi, tolerance);
}

}  // namespace curdle::site
