#include "site/spline_fit.h"

#include <array>
#include <cmath>

namespace curdle::site {
namespace {

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1]}; }
Point scaled(const Point& a, double k) { return {a[0] * k, a[1] * k}; }
double length(const Point& a) { return std::hypot(a[0], a[1]); }
double cross(const Point& a, const Point& b) { return std::fabs(a[0] * b[1] - a[1] * b[0]); }

// The tangent directions at the first and last fit point from five points around each
// (Akima's estimate, with the polygon extended by reflection at its ends), as CAD programs
// estimate them when the drawing stores none.
std::array<Point, 2> five_point_tangents(const std::vector<Point>& p) {
  const size_t n = p.size();
  if (n < 3) return {minus(p[1], p[0]), minus(p[1], p[0])};
  // q[1..n-1] are the chords; q[0], q[n], q[n+1] and q[n+2] (standing for q[-1]) extend them.
  std::vector<Point> q(n + 3);
  for (size_t k = 1; k < n; ++k) q[k] = minus(p[k], p[k - 1]);
  q[0] = minus(scaled(q[1], 2), q[2]);
  q[n] = minus(scaled(q[n - 1], 2), q[n - 2]);
  q[n + 1] = minus(scaled(q[n], 2), q[n - 1]);
  q[n + 2] = minus(scaled(q[0], 2), q[1]);
  auto at = [&](size_t k) {
    const Point& before = k == 0 ? q[n + 2] : q[k - 1];
    const double v1 = cross(before, q[k]), v2 = cross(q[k + 1], q[k + 2]);
    const double alpha = v1 + v2 > 0 ? v1 / (v1 + v2) : 0.5;
    return Point{(1 - alpha) * q[k][0] + alpha * q[k + 1][0],
                 (1 - alpha) * q[k][1] + alpha * q[k + 1][1]};
  };
  return {at(0), at(n - 1)};
}

// The cubic basis functions that are not zero at t, N[span-3 .. span] (The NURBS Book, A2.2).
std::array<double, 4> basis(const std::vector<double>& knots, size_t span, double t) {
  std::array<double, 4> n{1, 0, 0, 0};
  std::array<double, 4> left{}, right{};
  for (size_t j = 1; j <= 3; ++j) {
    left[j] = t - knots[span + 1 - j];
    right[j] = knots[span + j] - t;
    double saved = 0;
    for (size_t r = 0; r < j; ++r) {
      const double denominator = right[r + 1] + left[j - r];
      const double temp = denominator != 0 ? n[r] / denominator : 0;
      n[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    n[j] = saved;
  }
  return n;
}

}  // namespace

KnotSpacing knot_spacing_of(long long flags) {
  if (flags & 64) return KnotSpacing::square_root_chord;
  if (flags & 128) return KnotSpacing::uniform;
  return KnotSpacing::chord;
}

std::optional<CubicSpline> spline_through(const std::vector<Point>& given,
                                          std::optional<Point> start_tangent,
                                          std::optional<Point> end_tangent, KnotSpacing spacing) {
  std::vector<Point> fit;
  for (const Point& p : given) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return std::nullopt;
    if (fit.empty() || p != fit.back()) fit.push_back(p);
  }
  if (fit.size() < 2) return std::nullopt;
  const size_t n = fit.size() - 1;  // the last fit point's index
  // The parameters, 0 to 1, spaced as the drawing says.
  std::vector<double> t(n + 1, 0.0);
  double total = 0;
  for (size_t k = 1; k <= n; ++k) {
    const double chord = length(minus(fit[k], fit[k - 1]));
    const double step = spacing == KnotSpacing::chord               ? chord
                        : spacing == KnotSpacing::square_root_chord ? std::sqrt(chord)
                                                                    : 1.0;
    t[k] = total += step;
  }
  if (!(total > 0) || !std::isfinite(total)) return std::nullopt;
  for (double& v : t) v /= total;
  t[n] = 1;

  // The end derivatives: the stored directions or the estimate, as long as the end chord over
  // its parameter step (for chord length: the fit polygon's length, as CAD makes them).
  const std::array<Point, 2> estimated = five_point_tangents(fit);
  auto derivative = [&](std::optional<Point> stored, const Point& guess, double magnitude) {
    const Point d = stored && length(*stored) > 0 ? *stored : guess;
    const double l = length(d);
    return l > 0 && std::isfinite(l) && std::isfinite(magnitude) ? scaled(d, magnitude / l)
                                                                 : minus(fit[n], fit[0]);
  };
  const Point d0 = derivative(start_tangent, estimated[0], length(minus(fit[1], fit[0])) / t[1]);
  const Point d1 =
      derivative(end_tangent, estimated[1], length(minus(fit[n], fit[n - 1])) / (1 - t[n - 1]));

  // n + 3 control points over the clamped "natural" knots 0,0,0,0, t1 .. t(n-1), 1,1,1,1.
  const size_t m = n + 3;
  CubicSpline s;
  s.knots.assign(4, 0.0);
  for (size_t k = 1; k < n; ++k) s.knots.push_back(t[k]);
  s.knots.insert(s.knots.end(), 4, 1.0);

  // One equation a row: the curve through each fit point, and the two end derivatives (rows 1
  // and n + 1). Row r's unknowns lie within columns r - 2 .. r + 2, so the system is banded
  // and, being totally positive but for the derivative rows' plain differences, is solved
  // without pivoting in linear time.
  constexpr int kBand = 2;
  std::vector<std::array<double, 2 * kBand + 1>> a(m);
  std::vector<Point> rhs(m);
  auto set = [&](size_t row, size_t column, double v) {
    const long offset = static_cast<long>(column) - static_cast<long>(row) + kBand;
    if (v == 0) return true;
    if (offset < 0 || offset > 2 * kBand) return false;
    a[row][static_cast<size_t>(offset)] = v;
    return true;
  };
  auto through = [&](size_t row, size_t k) {
    size_t span = 3;
    while (span + 1 < m && t[k] >= s.knots[span + 1]) ++span;
    const std::array<double, 4> b = basis(s.knots, span, t[k]);
    for (size_t j = 0; j < 4; ++j)
      if (!set(row, span - 3 + j, b[j])) return false;
    rhs[row] = fit[k];
    return true;
  };
  if (!through(0, 0)) return std::nullopt;
  set(1, 0, -1), set(1, 1, 1);
  rhs[1] = scaled(d0, s.knots[4] / 3);
  for (size_t k = 1; k < n; ++k)
    if (!through(k + 1, k)) return std::nullopt;
  set(n + 1, n + 1, -1), set(n + 1, n + 2, 1);
  rhs[n + 1] = scaled(d1, (1 - s.knots[m - 1]) / 3);
  if (!through(n + 2, n)) return std::nullopt;

  auto entry = [&](size_t row, size_t column) -> double& { return a[row][column + kBand - row]; };
  for (size_t j = 0; j < m; ++j) {
    const double pivot = entry(j, j);
    if (!(std::fabs(pivot) > 1e-300)) return std::nullopt;
    for (size_t i = j + 1; i < m && i <= j + kBand; ++i) {
      const double factor = entry(i, j) / pivot;
      if (factor == 0) continue;
      for (size_t c = j; c <= j + kBand && c < m; ++c) entry(i, c) -= factor * entry(j, c);
      rhs[i] = minus(rhs[i], scaled(rhs[j], factor));
    }
  }
  s.control.assign(m, Point{0, 0});
  for (size_t j = m; j-- > 0;) {
    Point v = rhs[j];
    for (size_t c = j + 1; c <= j + kBand && c < m; ++c)
      v = minus(v, scaled(s.control[c], entry(j, c)));
    s.control[j] = scaled(v, 1 / entry(j, j));
    if (!std::isfinite(s.control[j][0]) || !std::isfinite(s.control[j][1])) return std::nullopt;
  }
  return s;
}

}  // namespace curdle::site
