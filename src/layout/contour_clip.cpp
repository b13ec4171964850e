#include "layout/contour_clip.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "layout/box_clip.h"

namespace curdle {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Point = std::array<double, 2>;

struct Edge {
  Point from, to;
  double bulge = 0;
};

Point on_arc(const Arc& a, double t) {
  const double angle = a.start_angle() + a.sweep * t;
  return {a.centre[0] + a.radius * std::cos(angle), a.centre[1] + a.radius * std::sin(angle)};
}

// The part of each edge on the kept side of the line `value` along `axis` (`low`: keep what
// lies at or above it), arcs split where their circle crosses the line; consecutive kept parts
// are joined along the line where the boundary left and came back.
std::vector<Edge> clip_side(const std::vector<Edge>& edges, int axis, double value, bool low) {
  const auto inside = [&](const Point& p) { return low ? p[axis] >= value : p[axis] <= value; };
  std::vector<Edge> kept;
  for (const Edge& e : edges) {
    if (e.bulge == 0) {
      const bool ia = inside(e.from), ib = inside(e.to);
      if (ia && ib) {
        kept.push_back(e);
      } else if (ia != ib) {
        const double t = (value - e.from[axis]) / (e.to[axis] - e.from[axis]);
        Point p = e.from;
        p[axis] = value;
        p[1 - axis] = e.from[1 - axis] + t * (e.to[1 - axis] - e.from[1 - axis]);
        kept.push_back(ia ? Edge{e.from, p, 0} : Edge{p, e.to, 0});
      }
      continue;
    }
    // An arc: where its circle meets the line, as shares of its sweep.
    const Arc a = arc_between({e.from[0], e.from[1], e.bulge}, {e.to[0], e.to[1], 0});
    std::vector<double> cuts{0, 1};
    const double offset = (value - a.centre[axis]) / a.radius;
    if (std::fabs(offset) < 1) {
      const double base = axis == 0 ? std::acos(offset) : std::asin(offset);
      for (const double angle : {base, axis == 0 ? -base : kPi - base}) {
        double turn = (angle - a.start_angle()) / a.sweep;  // in sweeps; shift by whole turns
        const double per_turn = 2 * kPi / std::fabs(a.sweep);
        turn -= std::floor(turn / per_turn) * per_turn;
        if (turn > 1e-12 && turn < 1 - 1e-12) cuts.push_back(turn);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
      const double t0 = cuts[i], t1 = cuts[i + 1];
      if (!inside(on_arc(a, (t0 + t1) / 2))) continue;
      Point p0 = t0 == 0 ? e.from : on_arc(a, t0), p1 = t1 == 1 ? e.to : on_arc(a, t1);
      if (t0 > 0) p0[axis] = value;  // on the line exactly
      if (t1 < 1) p1[axis] = value;
      kept.push_back({p0, p1, bulge_of_sweep(a.sweep * (t1 - t0))});
    }
  }
  // Where one kept part ends away from the next one's start, the boundary ran outside: the
  // part between them runs along the line.
  std::vector<Edge> joined;
  for (size_t i = 0; i < kept.size(); ++i) {
    joined.push_back(kept[i]);
    const Point& next = kept[(i + 1) % kept.size()].from;
    if (std::hypot(kept[i].to[0] - next[0], kept[i].to[1] - next[1]) > 1e-9)
      joined.push_back({kept[i].to, next, 0});
  }
  return joined;
}

}  // namespace

std::optional<Contour> clip_contour_to_box(const Contour& contour, const Rect& box,
                                           double tolerance) {
  const std::optional<Polygon> chords = clip_to_box(flatten(contour, tolerance), box);
  if (!chords) return std::nullopt;
  if (chords->empty()) return Contour{};
  std::vector<Edge> edges;
  for (size_t i = 0; i < contour.size(); ++i) {
    const ContourVertex& a = contour[i];
    const ContourVertex& b = contour[(i + 1) % contour.size()];
    edges.push_back({{a.x, a.y}, {b.x, b.y}, a.bulge});
  }
  edges = clip_side(edges, 0, box.x, true);
  edges = clip_side(edges, 0, box.right(), false);
  edges = clip_side(edges, 1, box.y, true);
  edges = clip_side(edges, 1, box.top(), false);
  Contour out;
  for (const Edge& e : edges)
    if (std::hypot(e.to[0] - e.from[0], e.to[1] - e.from[1]) > 1e-9)
      out.push_back({e.from[0], e.from[1], e.bulge});
  if (out.size() < 2) return std::nullopt;
  return out;
}

}  // namespace curdle
