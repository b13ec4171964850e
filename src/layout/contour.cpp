// Bulge arithmetic: for an edge a → b of chord c and bulge k, the arc's sagitta is k c / 2, its
// radius c (1 + k²) / (4 |k|), and its centre lies c (1 - k²) / (4 k) to the left of the chord's
// middle (so that a positive bulge, counter-clockwise, swells to the chord's right).
#include "layout/contour.h"

#include <algorithm>
#include <cmath>

#include "layout/zone.h"

namespace curdle {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The signed area of a circular segment of `sweep` radians and radius r: what an arc edge adds
// to the area of the polygon of its chords (negative where it swells inwards).
double segment_area(double radius, double sweep) {
  return radius * radius / 2 * (sweep - std::sin(sweep));
}

}  // namespace

double Arc::start_angle() const { return std::atan2(from[1] - centre[1], from[0] - centre[0]); }

Arc arc_between(const ContourVertex& a, const ContourVertex& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double chord = std::hypot(dx, dy);
  const double k = a.bulge;
  Arc arc;
  arc.from = {a.x, a.y};
  arc.to = {b.x, b.y};
  arc.sweep = 4 * std::atan(k);
  arc.radius = chord * (1 + k * k) / (4 * std::fabs(k));
  const double offset = chord * (1 - k * k) / (4 * k);  // along the chord's left normal
  const double nx = chord > 0 ? -dy / chord : 0, ny = chord > 0 ? dx / chord : 0;
  arc.centre = {(a.x + b.x) / 2 + nx * offset, (a.y + b.y) / 2 + ny * offset};
  return arc;
}

double bulge_of_sweep(double sweep) { return std::tan(sweep / 4); }

bool has_arcs(const Contour& contour) { return arc_count(contour) > 0; }

size_t arc_count(const Contour& contour) {
  return static_cast<size_t>(std::count_if(contour.begin(), contour.end(),
                                           [](const ContourVertex& v) { return v.bulge != 0; }));
}

std::optional<Rect> as_rectangle(const Contour& c) {
  if (c.size() != 4 || has_arcs(c)) return std::nullopt;
  const auto rects = as_rectangles(flatten(c, 1));
  if (!rects || rects->size() != 1) return std::nullopt;
  return rects->front();
}

Contour contour_of(const Polygon& polygon) {
  Contour c;
  c.reserve(polygon.size());
  for (const auto& p : polygon) c.push_back({p[0], p[1], 0});
  return c;
}

Polygon flatten(const Contour& contour, double tolerance) {
  Polygon polygon;
  polygon.reserve(contour.size());
  for (size_t i = 0; i < contour.size(); ++i) {
    const ContourVertex& a = contour[i];
    polygon.push_back({a.x, a.y});
    if (a.bulge == 0) continue;
    const Arc arc = arc_between(a, contour[(i + 1) % contour.size()]);
    // A chord of angle φ strays r (1 - cos(φ / 2)) from its arc.
    const double most = tolerance < arc.radius ? 2 * std::acos(1 - tolerance / arc.radius) : kPi;
    const double step = std::min(most, kPi / 4);
    // An arc too flat to measure (a bulge of 1e-300: an infinite radius) is its chord; no arc
    // takes more than a million chords, whatever its radius and the tolerance.
    const double wanted = std::ceil(std::fabs(arc.sweep) / step - 1e-9);
    if (!std::isfinite(arc.radius) || !(wanted >= 1)) continue;
    const auto chords = static_cast<size_t>(std::min(wanted, 1e6));
    const double start = arc.start_angle();
    for (size_t k = 1; k < chords; ++k) {
      const double angle = start + arc.sweep * static_cast<double>(k) / static_cast<double>(chords);
      polygon.push_back({arc.centre[0] + arc.radius * std::cos(angle),
                         arc.centre[1] + arc.radius * std::sin(angle)});
    }
  }
  return polygon;
}

double contour_area(const Contour& contour) {
  double twice = 0, arcs = 0;
  const size_t n = contour.size();
  for (size_t i = 0; i < n; ++i) {
    const ContourVertex& a = contour[i];
    const ContourVertex& b = contour[(i + 1) % n];
    twice += a.x * b.y - b.x * a.y;
    if (a.bulge != 0) {
      const Arc arc = arc_between(a, b);
      arcs += segment_area(arc.radius, arc.sweep);
    }
  }
  return std::fabs(twice / 2 + arcs);
}

Rect contour_bounds(const Contour& contour) {
  if (contour.empty()) return {};
  double x0 = contour[0].x, y0 = contour[0].y, x1 = x0, y1 = y0;
  auto add = [&](double x, double y) {
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  };
  for (size_t i = 0; i < contour.size(); ++i) {
    const ContourVertex& a = contour[i];
    add(a.x, a.y);
    if (a.bulge == 0) continue;
    // The arc reaches each axis direction (0, 90, 180, 270°) that it sweeps through.
    const Arc arc = arc_between(a, contour[(i + 1) % contour.size()]);
    const double start = arc.start_angle();
    for (int q = -8; q <= 8; ++q) {
      const double angle = q * kPi / 2;
      const double t = (angle - start) / arc.sweep;
      if (t > 0 && t < 1)
        add(arc.centre[0] + arc.radius * std::cos(angle),
            arc.centre[1] + arc.radius * std::sin(angle));
    }
  }
  return Rect{x0, y0, x1 - x0, y1 - y0};
}

Contour transformed(const Contour& contour, double scale, double dx, double dy) {
  Contour c = contour;
  for (ContourVertex& v : c) v = {v.x * scale + dx, v.y * scale + dy, v.bulge};
  return c;
}

}  // namespace curdle
