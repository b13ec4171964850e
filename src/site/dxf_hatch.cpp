#include "site/dxf_hatch.h"

#include <fmt/format.h>

#include <cmath>

#include "site/curves.h"
#include "site/drawing.h"

namespace curdle::site {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One edge of a path: 1 line, 2 circular arc, 3 elliptic arc, 4 spline, read in order.
template <class Number>
Contour hatch_edge(int64_t edge, Number& number, const std::string& file, const std::string& name,
                   const std::string& layer, double tolerance, size_t& flattened) {
  if (edge == 1) {
    const double x1 = number(10), y1 = number(20), x2 = number(11), y2 = number(21);
    return {{x1, y1, 0}, {x2, y2, 0}};
  }
  if (edge == 2 || edge == 3) {
    const double cx = number(10), cy = number(20);
    double mx = 0, my = 0, ratio = 1, radius = 0;
    if (edge == 2) {
      radius = number(40);
    } else {
      mx = number(11), my = number(21), ratio = number(40);
    }
    double from = number(50) * kPi / 180, to = number(51) * kPi / 180;
    const bool ccw = number(73) != 0;
    // A clockwise edge stores its angles mirrored: it runs from -from to -to, clockwise.
    if (!ccw) from = -from, to = -to;
    double sweep = ccw ? to - from : from - to;
    while (sweep <= 0) sweep += 2 * kPi;
    if (sweep > 2 * kPi) sweep = 2 * kPi;
    if (edge == 2) {
      if (!(radius > 0)) return {};
      Contour arc;
      const int halves = sweep > kPi ? 2 : 1;
      const double step = (ccw ? 1 : -1) * sweep / halves;
      for (int h = 0; h <= halves; ++h) {
        const double a = from + step * h;
        arc.push_back({cx + radius * std::cos(a), cy + radius * std::sin(a),
                       h < halves ? tidy_bulge(std::tan(step / 4)) : 0});
      }
      return arc;
    }
    const double major = std::hypot(mx, my);
    if (!(major > 0) || !(ratio > 0)) return {};
    // Angles of an elliptic edge are of the ellipse's parameter.
    const Point minor{-my * ratio, mx * ratio};
    const double t0 = from, t1 = ccw ? from + sweep : from - sweep;
    Contour arc;
    for (const Point& p : flatten_curve(
             [&](double t) {
               return Point{cx + mx * std::cos(t) + minor[0] * std::sin(t),
                            cy + my * std::cos(t) + minor[1] * std::sin(t)};
             },
             t0, t1, tolerance))
      arc.push_back({p[0], p[1], 0});
    ++flattened;
    return arc;
  }
  if (edge == 4) {
    const auto degree = static_cast<int>(number(94));
    const bool rational = number(73) != 0;
    number(74);
    const auto knot_count = static_cast<int64_t>(number(95));
    const auto control_count = static_cast<int64_t>(number(96));
    std::vector<double> knots, weights;
    std::vector<Point> control;
    for (int64_t k = 0; k < knot_count && k < static_cast<int64_t>(kMostVertices); ++k)
      knots.push_back(number(40));
    for (int64_t k = 0; k < control_count && k < static_cast<int64_t>(kMostVertices); ++k) {
      const double x = number(10), y = number(20);
      control.push_back({x, y});
      if (rational) weights.push_back(number(42));
    }
    Contour arc;
    for (const Point& p : flatten_spline(degree, knots, control, weights, tolerance))
      arc.push_back({p[0], p[1], 0});
    if (arc.empty())
      throw InputError(
          fmt::format("{}: the {} on layer \"{}\" has a spline edge whose knots do "
                      "not fit its control points; the file is damaged",
                      file, name, layer));
    ++flattened;
    return arc;
  }
  throw InputError(
      fmt::format("{}: the {} on layer \"{}\" has a boundary edge of type {}, "
                  "which no DXF has (1 line, 2 arc, 3 elliptic arc, 4 spline)",
                  file, name, layer, edge));
}

// Edges of a hatch's path follow each other; one drawn the other way round is turned.
void append_edge(Contour& path, Contour piece) {
  if (piece.empty()) return;
  if (path.empty()) {
    path = std::move(piece);
    return;
  }
  auto gap = [](const ContourVertex& a, const ContourVertex& b) {
    return std::hypot(a.x - b.x, a.y - b.y);
  };
  if (gap(path.back(), piece.back()) < gap(path.back(), piece.front())) {
    Contour r(piece.rbegin(), piece.rend());
    for (size_t k = 0; k + 1 < r.size(); ++k) r[k].bulge = -r[k + 1].bulge;
    r.back().bulge = 0;
    piece = std::move(r);
  }
  path.back().bulge = piece.front().bulge;
  path.insert(path.end(), piece.begin() + 1, piece.end());
}

}  // namespace

std::optional<HatchBoundaries> hatch_boundaries(const std::vector<DxfGroup>& g,
                                                const DxfGroups& numbers, const std::string& name,
                                                const std::string& layer, double tolerance) {
  size_t i = 0;
  while (i < g.size() && g[i].code != 91) ++i;
  if (i == g.size()) return std::nullopt;
  HatchBoundaries out;
  const int64_t loops = numbers.integer(g[i++], name);
  auto expect = [&](int code) -> const DxfGroup* {
    // The next group of that code before the loop's end, skipping what is not asked for.
    while (i < g.size() && g[i].code != code) {
      if (g[i].code == 92 || g[i].code == 75 || g[i].code == 98) return nullptr;
      ++i;
    }
    return i < g.size() ? &g[i++] : nullptr;
  };
  auto number = [&](int code) {
    const DxfGroup* found = expect(code);
    if (!found)
      throw InputError(
          fmt::format("{}: the {} on layer \"{}\" has a boundary path without "
                      "group {}; the file is damaged: export it again",
                      numbers.file(), name, layer, code));
    return numbers.real(*found, name);
  };
  for (int64_t loop = 0; loop < loops && loop < 10000; ++loop) {
    while (i < g.size() && g[i].code != 92) ++i;
    if (i == g.size()) break;
    const int64_t type = numbers.integer(g[i++], name);
    Contour path;
    if (type & 2) {  // a polyline: its vertices with bulges
      const bool bulges = number(72) != 0;
      number(73);
      const auto count = static_cast<int64_t>(number(93));
      for (int64_t k = 0; k < count && k < static_cast<int64_t>(kMostVertices); ++k) {
        const double x = number(10), y = number(20);
        const double b = bulges && i < g.size() && g[i].code == 42 ? numbers.real(g[i++], name) : 0;
        path.push_back({x, y, tidy_bulge(b)});
      }
    } else {
      const auto edges = static_cast<int64_t>(number(93));
      Contour loop_path;
      for (int64_t k = 0; k < edges && k < 100000; ++k) {
        const auto edge = static_cast<int64_t>(number(72));
        append_edge(loop_path, hatch_edge(edge, number, numbers.file(), name, layer, tolerance,
                                          out.flattened));
      }
      path = std::move(loop_path);
    }
    if (path.size() > 2 &&
        std::hypot(path.back().x - path.front().x, path.back().y - path.front().y) <=
            1e-9 * (1 + std::fabs(path.front().x)))
      path.pop_back();
    if (path.size() >= 2) out.loops.push_back(std::move(path));
  }
  return out;
}

}  // namespace curdle::site
