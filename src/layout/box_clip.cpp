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
  const auto inside = [&](const Point& p) { return low ? p[axis] >= edge : p[axis] <= edge; };
  for (size_t i = 0; i < in.size(); ++i) {
    const Point& a = in[i];
    const Point& b = in[(i + 1) % in.size()];
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

}  // namespace

std::optional<Polygon> clip_to_box(const Polygon& polygon, const Rect& box) {
  const size_t n = polygon.size();
  if (n < 3) return std::nullopt;
  size_t entries = 0, inside = 0;
  for (size_t i = 0; i < n; ++i) {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % n];
    const bool ia = in_box(a, box);
    inside += ia;
    if (!ia && segment_meets(a, b, box)) ++entries;
  }
  if (inside == n) return polygon;
  if (entries == 0)
    return contains(polygon, box.x + box.w / 2, box.y + box.h / 2) ? rect_polygon(box) : Polygon{};
  if (entries > 1) return std::nullopt;
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

}  // namespace curdle
