#include "layout/union.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <algorithm>
#include <cmath>
#include <list>
#include <optional>

#include "layout/box_clip.h"

namespace curdle {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

ExactPolygon exact(const std::vector<std::array<double, 2>>& points) {
  ExactPolygon p;
  for (const auto& v : points) p.push_back(Kernel::Point_2(v[0], v[1]));
  if (p.size() >= 3 && p.is_clockwise_oriented()) p.reverse_orientation();
  return p;
}

ExactPolygon exact(const Rect& r) { return exact(rect_polygon(r)); }

}  // namespace

std::vector<Outline> outline_parts(const Outline& outline) {
  std::vector<Outline> parts;
  for (const Ring& ring : outline.rings) {
    double twice = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
      const auto& a = ring[i];
      const auto& b = ring[(i + 1) % ring.size()];
      twice += a[0] * b[1] - b[0] * a[1];
    }
    if (twice > 0 || parts.empty()) parts.emplace_back();
    parts.back().rings.push_back(ring);
    parts.back().area += twice / 2;
  }
  return parts;
}

Outline joined(const std::vector<Outline>& parts) {
  Outline all;
  for (const Outline& part : parts) {
    all.rings.insert(all.rings.end(), part.rings.begin(), part.rings.end());
    all.area += part.area;
  }
  return all;
}

namespace {

// A ring as simple loops: a boundary that touches itself at a vertex (two triangles of what an
// outline cuts away meeting at a point) is split there, so that each loop is a simple polygon,
// as CGAL's Polygon_2 needs.
std::vector<Ring> simple_loops(const Ring& ring) {
  std::vector<Ring> loops;
  Ring path;
  for (const auto& v : ring) {
    const auto again = std::find(path.begin(), path.end(), v);
    if (again != path.end()) {
      loops.emplace_back(again, path.end());
      path.erase(again + 1, path.end());
      continue;
    }
    path.push_back(v);
  }
  if (path.size() >= 3) loops.push_back(std::move(path));
  std::erase_if(loops, [](const Ring& loop) { return loop.size() < 3; });
  return loops;
}

// Outlines (outer rings and their islands, as outlines_of makes them) as a polygon set: each
// part its outer loops less its islands' loops.
CGAL::Polygon_set_2<Kernel> set_of(const std::vector<Outline>& outlines) {
  CGAL::Polygon_set_2<Kernel> set;
  for (const Outline& whole : outlines)
    for (const Outline& o : outline_parts(whole)) {
      CGAL::Polygon_set_2<Kernel> part;
      for (const Ring& loop : simple_loops(o.rings[0])) part.join(exact(loop));
      for (size_t i = 1; i < o.rings.size(); ++i)
        for (const Ring& loop : simple_loops(o.rings[i])) part.difference(exact(loop));
      set.join(part);
    }
  return set;
}

Ring ring_of(const ExactPolygon& p) {
  Ring r;
  for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v)
    r.push_back({CGAL::to_double(v->x()), CGAL::to_double(v->y())});
  return r;
}

}  // namespace

Ring polygonise(const Circle& c, double tolerance) {
  const double r = c.d / 2;
  const double step =
      tolerance >= r ? 3.14159265358979323846 / 3 : 2 * std::acos(1 - tolerance / r);
  // A multiple of 4 vertices from angle 0: the quarter points are vertices, so that the ring's
  // box is the circle's (a GIS's extent, the schedule's width and height, agree).
  const int n = 4 * std::max(2, static_cast<int>(std::ceil(2 * 3.14159265358979323846 / step / 4)));
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / n;
    ring.push_back({c.cx + r * std::cos(a), c.cy + r * std::sin(a)});
  }
  return ring;
}

std::vector<Outline> outlines_of(const CGAL::Polygon_set_2<Kernel>& set);

std::vector<Outline> union_of_circles(const std::vector<Circle>& circles, double tolerance) {
  CGAL::Polygon_set_2<Kernel> set;
  for (const Circle& c : circles) {
    ExactPolygon p;
    for (const auto& v : polygonise(c, tolerance)) p.push_back(Kernel::Point_2(v[0], v[1]));
    set.join(p);
  }
  return outlines_of(set);
}

std::vector<Outline> union_of_rects(const std::vector<Rect>& rects) {
  CGAL::Polygon_set_2<Kernel> set;
  for (const Rect& r : rects) {
    if (r.w <= 0 || r.h <= 0) continue;
    ExactPolygon p;
    p.push_back(Kernel::Point_2(r.x, r.y));
    p.push_back(Kernel::Point_2(r.right(), r.y));
    p.push_back(Kernel::Point_2(r.right(), r.top()));
    p.push_back(Kernel::Point_2(r.x, r.top()));
    set.join(p);
  }
  std::vector<Outline> out = outlines_of(set);
  // Joined edges leave collinear vertices behind: drop them, so that an L is six corners.
  for (Outline& o : out)
    for (Ring& ring : o.rings) {
      Ring kept;
      const size_t n = ring.size();
      for (size_t i = 0; i < n; ++i) {
        const auto& a = ring[(i + n - 1) % n];
        const auto& b = ring[i];
        const auto& c = ring[(i + 1) % n];
        const double cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
        if (std::fabs(cross) > 1e-9) kept.push_back(b);
      }
      ring = std::move(kept);
    }
  return out;
}

void PolygonCuts::index() {
  outline_index_ = outline.empty() ? nullptr : std::make_shared<const PolygonIndex>(outline);
  hole_index_.clear();
  for (const Polygon& h : holes) hole_index_.push_back(std::make_shared<const PolygonIndex>(h));
}

Crossing PolygonCuts::outline_crossing(const Rect& r) const {
  return outline_index_ ? outline_index_->crossing(r) : crossing(r, outline);
}

std::optional<Polygon> PolygonCuts::outline_near(const Rect& box) const {
  return outline_index_ ? clip_to_box(*outline_index_, box) : clip_to_box(outline, box);
}

Crossing PolygonCuts::hole_crossing(size_t hole, const Rect& r) const {
  return hole < hole_index_.size() ? hole_index_[hole]->crossing(r) : crossing(r, holes[hole]);
}

namespace {

Rect bounds_of(const std::vector<std::array<double, 2>>& points) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& v : points)
    x0 = std::min(x0, v[0]), y0 = std::min(y0, v[1]), x1 = std::max(x1, v[0]),
    y1 = std::max(y1, v[1]);
  return Rect{x0, y0, x1 - x0, y1 - y0};
}

// The piece's region within the outline and off the holes: the outline clipped to a box a
// millimetre round the piece where that is exact (box_clip.h), holes that do not reach the box
// left out. Exact either way; only the work differs.
void cut_with(CGAL::Polygon_set_2<Kernel>& set, const Rect& piece, const PolygonCuts& cuts) {
  const Rect box{piece.x - 1, piece.y - 1, piece.w + 2, piece.h + 2};
  if (!cuts.outline.empty()) {
    const std::optional<Polygon> near = cuts.outline_near(box);
    if (near && near->empty()) {
      set.clear();
      return;
    }
    set.intersection(exact(near ? *near : cuts.outline));
  }
  for (const Polygon& hole : cuts.holes)
    if (overlaps(bounds_of(hole), box)) set.difference(exact(hole));
}

}  // namespace

std::vector<Outline> cut_along(const std::vector<Rect>& rects, const PolygonCuts& cuts) {
  CGAL::Polygon_set_2<Kernel> set;
  std::vector<std::array<double, 2>> corners;
  for (const Rect& r : rects)
    if (r.w > 0 && r.h > 0) {
      set.join(exact(r));
      corners.insert(corners.end(), {{r.x, r.y}, {r.right(), r.top()}});
    }
  if (corners.empty()) return {};
  cut_with(set, bounds_of(corners), cuts);
  return outlines_of(set);
}

std::vector<Outline> cut_unit(const Ring& unit, const Rect& surface, const std::vector<Rect>& holes,
                              const PolygonCuts& cuts) {
  CGAL::Polygon_set_2<Kernel> set;
  set.join(exact(unit));
  set.intersection(exact(surface));
  for (const Rect& h : holes)
    if (h.w > 0 && h.h > 0) set.difference(exact(h));
  cut_with(set, bounds_of(unit), cuts);
  return outlines_of(set);
}

std::vector<Outline> cut_away(const Rect& surface, const PolygonCuts& cuts) {
  CGAL::Polygon_set_2<Kernel> set;
  if (!cuts.outline.empty()) {
    set.join(exact(surface));
    set.difference(exact(cuts.outline));
  }
  // The holes joined among themselves first, then to the rest at once: one overlay with a
  // surveyed outline instead of one a hole (twenty tree pits took 0.9 s one by one).
  std::vector<ExactPolygon> holes;
  for (const Polygon& hole : cuts.holes) holes.push_back(exact(hole));
  if (!holes.empty()) {
    CGAL::Polygon_set_2<Kernel> all;
    all.join(holes.begin(), holes.end());
    set.join(all);
  }
  set.intersection(exact(surface));
  return outlines_of(set);
}

std::vector<Outline> surfaced(const Rect& surface, const std::vector<Rect>& holes,
                              const std::vector<Outline>& cut_away) {
  CGAL::Polygon_set_2<Kernel> set;
  set.join(exact(surface));
  for (const Rect& h : holes)
    if (h.w > 0 && h.h > 0) set.difference(exact(h));
  set.difference(set_of(cut_away));
  return outlines_of(set);
}

std::vector<Outline> clip_outline(const Rect& r, const Outline& outline) {
  if (r.w <= 0 || r.h <= 0) return {};
  CGAL::Polygon_set_2<Kernel> set;
  set.join(set_of({outline}));
  set.intersection(exact(r));
  return outlines_of(set);
}

double area_within(const Rect& r, const std::vector<Outline>& outlines) {
  if (r.w <= 0 || r.h <= 0) return 0;
  std::vector<Outline> near;  // only those whose box meets r: most strips meet none
  for (const Outline& o : outlines) {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const auto& v : o.rings.empty() ? Ring{} : o.rings[0])
      x0 = std::min(x0, v[0]), y0 = std::min(y0, v[1]), x1 = std::max(x1, v[0]),
      y1 = std::max(y1, v[1]);
    if (x0 < r.right() && x1 > r.x && y0 < r.top() && y1 > r.y) near.push_back(o);
  }
  if (near.empty()) return 0;
  CGAL::Polygon_set_2<Kernel> set = set_of(near);
  set.intersection(exact(r));
  double area = 0;
  for (const Outline& o : outlines_of(set)) area += o.area;
  return area;
}

double area_inside(const std::vector<Outline>& outlines, const Polygon& polygon) {
  if (outlines.empty() || polygon.size() < 3) return 0;
  ExactPolygon zone = exact(polygon);
  if (!zone.is_simple()) return 0;  // zones are checked simple when read
  if (zone.is_clockwise_oriented()) zone.reverse_orientation();
  CGAL::Polygon_set_2<Kernel> set = set_of(outlines);
  set.intersection(zone);
  double area = 0;
  for (const Outline& o : outlines_of(set)) area += o.area;
  return area;
}

std::vector<Outline> outlines_of(const CGAL::Polygon_set_2<Kernel>& set) {
  std::list<PolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  std::vector<Outline> out;
  for (const PolygonWithHoles& part : parts) {
    Outline o;
    o.rings.push_back(ring_of(part.outer_boundary()));
    Kernel::FT area = part.outer_boundary().area();
    for (auto h = part.holes_begin(); h != part.holes_end(); ++h) {
      o.rings.push_back(ring_of(*h));
      area += h->area();  // islands run clockwise: their area is negative
    }
    o.area = CGAL::to_double(area);
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace curdle
