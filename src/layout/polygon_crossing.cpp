#include "layout/polygon_crossing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace curdle {
namespace {

using Point = std::array<double, 2>;

constexpr double kEps = 1e-9;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

bool on_segment(const Point& p, const Point& a, const Point& b) {
  return std::min(a[0], b[0]) - kEps <= p[0] && p[0] <= std::max(a[0], b[0]) + kEps &&
         std::min(a[1], b[1]) - kEps <= p[1] && p[1] <= std::max(a[1], b[1]) + kEps;
}

bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  if (((d1 > kEps && d2 < -kEps) || (d1 < -kEps && d2 > kEps)) &&
      ((d3 > kEps && d4 < -kEps) || (d3 < -kEps && d4 > kEps)))
    return true;
  return (std::fabs(d1) <= kEps && on_segment(a, c, d)) ||
         (std::fabs(d2) <= kEps && on_segment(b, c, d)) ||
         (std::fabs(d3) <= kEps && on_segment(c, a, b)) ||
         (std::fabs(d4) <= kEps && on_segment(d, a, b));
}

// A square grid over the polygon's box, `side` cells a side.
struct Grid {
  double x0, y0, w, h;
  uint32_t side;
  uint32_t column(double x) const { return index((x - x0) / w); }
  uint32_t row(double y) const { return index((y - y0) / h); }
  uint32_t index(double v) const {
    return static_cast<uint32_t>(std::clamp(v, 0.0, static_cast<double>(side - 1)));
  }
};

// Calls f(cell) for every cell the edge a-b passes through, grown by kEps: column by column,
// the rows its y spans over that column's width (a vertical edge, one column).
template <class F>
void for_cells_of(const Grid& g, const Point& a, const Point& b, F&& f) {
  const double lo = std::min(a[0], b[0]) - kEps, hi = std::max(a[0], b[0]) + kEps;
  const uint32_t first = g.column(lo), last = g.column(hi);
  auto y_at = [&](double x) {  // on the edge, x clamped to its ends
    const double t = std::clamp((x - a[0]) / (b[0] - a[0]), 0.0, 1.0);
    return a[1] + t * (b[1] - a[1]);
  };
  for (uint32_t c = first; c <= last; ++c) {
    double ylo = std::min(a[1], b[1]), yhi = std::max(a[1], b[1]);
    if (a[0] != b[0]) {
      const double from = std::max(lo, g.x0 + c * g.w), to = std::min(hi, g.x0 + (c + 1) * g.w);
      ylo = std::min(y_at(from), y_at(to)), yhi = std::max(y_at(from), y_at(to));
    }
    for (uint32_t r = g.row(ylo - kEps); r <= g.row(yhi + kEps); ++r) f(r * g.side + c);
  }
}

// How many (cell, edge) entries the grid files: what sets how fine it may be.
uint64_t entries(const Grid& g, const Polygon& polygon) {
  uint64_t n = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
    n += g.column(std::max(a[0], b[0]) + kEps) - g.column(std::min(a[0], b[0]) - kEps) +
         g.row(std::max(a[1], b[1]) + kEps) - g.row(std::min(a[1], b[1]) - kEps) + 2;
  }
  return n;
}

}  // namespace

std::optional<std::array<double, 2>> first_crossing(const Polygon& polygon) {
  const size_t n = polygon.size();
  if (n < 4) return std::nullopt;
  double x0 = polygon[0][0], y0 = polygon[0][1], x1 = x0, y1 = y0;
  for (const auto& p : polygon)
    x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]), x1 = std::max(x1, p[0]),
    y1 = std::max(y1, p[1]);
  // Four cells a side for every root of the corners' count, coarser until the entries stay
  // within 32 an edge or 4 M in all, 32 MB (a polygon of long edges crossing the whole grid).
  Grid g{x0, y0, 0, 0, static_cast<uint32_t>(std::clamp(4 * std::sqrt(double(n)), 1.0, 4096.0))};
  const uint64_t most = std::max<uint64_t>(32 * uint64_t{n}, uint64_t{1} << 22);
  uint64_t count = 0;
  for (;; g.side = std::max(1u, g.side / 2)) {
    g.w = std::max(x1 - x0, 1e-9) / g.side, g.h = std::max(y1 - y0, 1e-9) / g.side;
    count = entries(g, polygon);
    if (g.side == 1 || count <= most) break;
  }
  std::vector<uint64_t> filed;  // cell << 32 | edge, sorted: each cell's edges side by side
  filed.reserve(count);
  for (size_t i = 0; i < n; ++i)
    for_cells_of(g, polygon[i], polygon[(i + 1) % n],
                 [&](uint64_t cell) { filed.push_back(cell << 32 | i); });
  std::sort(filed.begin(), filed.end());
  for (size_t start = 0; start < filed.size();) {
    size_t end = start;
    while (end < filed.size() && filed[end] >> 32 == filed[start] >> 32) ++end;
    for (size_t p = start; p < end; ++p)
      for (size_t q = p + 1; q < end; ++q) {
        const size_t i = filed[p] & 0xffffffffu, j = filed[q] & 0xffffffffu;  // i < j: sorted
        if (j == i + 1 || (i == 0 && j == n - 1)) continue;
        const Point &a = polygon[i], &b = polygon[(i + 1) % n];
        const Point &c = polygon[j], &d = polygon[(j + 1) % n];
        if (!segments_meet(a, b, c, d)) continue;
        // Where they meet: the lines' intersection, or a shared end of touching edges.
        const double den = (b[0] - a[0]) * (d[1] - c[1]) - (b[1] - a[1]) * (d[0] - c[0]);
        if (std::fabs(den) < 1e-12) return c;
        const double t = ((c[0] - a[0]) * (d[1] - c[1]) - (c[1] - a[1]) * (d[0] - c[0])) / den;
        return std::array<double, 2>{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
      }
    start = end;
  }
  return std::nullopt;
}

}  // namespace curdle
