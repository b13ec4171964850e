#include "layout/box_clip.h"

#include <algorithm>
#include <cmath>

#include "layout/zone.h"

namespace curdle {
namespace {

using Point = std::array<double, 2>;

bool in_box(const Point& p, const Rect& b) {
  return p[0] >= b.x && p[0] <= b.right() && p[1] >= b.y && p[1] <= b.top();
}

// One side of the box: keep what lies at or inside `edge` along axis `axis` (0 x, 1 y),
// `low` for the side facing +axis. Crossings are put exactly on the side.
Polygon clip_side(const Polygon& in, int axis, double edge, bool low) {
  Polygon out;
  out.reserve(in.size() + 4);
  const auto inside = [&](const Point& p) { return low ? p[axis] >= edge : p[axis] <= edge; };
  for (size_t i = 0, n = in.size(); i < n; ++i) {
    const Point& a = in[i];
    const Point& b = in[i + 1 < n ? i + 1 : 0];
    const bool ia = inside(a), ib = inside(b);
    if (ia) out.push_back(a);
    if (ia != ib) {
      const double t = (edge - a[axis]) / (b[axis] - a[axis]);
      Point p;
      p[axis] = edge;
      p[1 - axis] = a[1 - axis] + t * (b[1 - axis] - a[1 - axis]);
      out.push_back(p);
    }
  }
  return out;
}

// What the clip is, from the polygon's corners inside the box and the edges that enter it
// from outside.
struct Meeting {
  size_t inside = 0, entries = 0;
};

void count_edge(const Polygon& polygon, size_t i, const Rect& box, Meeting& m) {
  const Point& a = polygon[i];
  const Point& b = polygon[i + 1 < polygon.size() ? i + 1 : 0];
  const bool ia = in_box(a, box);
  m.inside += ia;
  if (!ia && segment_meets(a, b, box)) ++m.entries;
}

// The clip itself, once the corners and entries are counted (`contains_centre` says whether
// the box's centre is inside the polygon).
template <class ContainsCentre>
std::optional<Polygon> clip_counted(const Polygon& polygon, const Rect& box, const Meeting& m,
                                    ContainsCentre contains_centre) {
  if (m.inside == polygon.size()) return polygon;
  if (m.entries == 0) return contains_centre() ? rect_polygon(box) : Polygon{};
  if (m.entries > 1) return std::nullopt;
  Polygon p = clip_side(polygon, 0, box.x, true);
  p = clip_side(p, 0, box.right(), false);
  p = clip_side(p, 1, box.y, true);
  p = clip_side(p, 1, box.top(), false);
  Polygon kept;
  for (const Point& v : p)
    if (kept.empty() || v != kept.back()) kept.push_back(v);
  while (kept.size() > 1 && kept.front() == kept.back()) kept.pop_back();
  if (kept.size() < 3 || polygon_area(kept) <= 0 || first_crossing(kept)) return std::nullopt;
  return kept;
}

}  // namespace

std::optional<Polygon> clip_to_box(const Polygon& polygon, const Rect& box) {
  if (polygon.size() < 3) return std::nullopt;
  Meeting m;
  for (size_t i = 0; i < polygon.size(); ++i) count_edge(polygon, i, box, m);
  return clip_counted(polygon, box, m,
                      [&] { return contains(polygon, box.x + box.w / 2, box.y + box.h / 2); });
}

std::optional<Polygon> clip_to_box(const PolygonIndex& index, const Rect& box) {
  const Polygon& polygon = index.polygon();
  if (polygon.size() < 3) return std::nullopt;
  // Rounding may let segment_meets take an edge that stops a hair short of the box: the edges
  // are looked for a millimetre (or a billionth of the coordinates) round it.
  const double far =
      std::max({std::abs(box.x), std::abs(box.right()), std::abs(box.y), std::abs(box.top())});
  const double margin = std::max(1.0, 1e-9 * far);
  Meeting m;
  for (const uint32_t i : index.edges_near(
           Rect{box.x - margin, box.y - margin, box.w + 2 * margin, box.h + 2 * margin}))
    count_edge(polygon, i, box, m);
  return clip_counted(polygon, box, m, [&] {
    return index.contains_as_polygon(box.x + box.w / 2, box.y + box.h / 2);
  });
}

}  // namespace curdle
