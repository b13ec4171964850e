#include "layout/zone.h"

#include <algorithm>
#include <cmath>

namespace curdle {
namespace {

constexpr double kEps = 1e-9;

}  // namespace

Polygon rect_polygon(const Rect& r) {
  return {{r.x, r.y}, {r.right(), r.y}, {r.right(), r.top()}, {r.x, r.top()}};
}

bool contains(const Polygon& polygon, double x, double y) {
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const auto& a = polygon[i];
    const auto& b = polygon[j];
    if ((a[1] > y) != (b[1] > y) && x < (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
  }
  return in;
}

double signed_area(const Polygon& polygon) {
  double twice = 0;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    twice += polygon[j][0] * polygon[i][1] - polygon[i][0] * polygon[j][1];
  return twice / 2;
}

double polygon_area(const Polygon& polygon) { return std::fabs(signed_area(polygon)); }

std::optional<std::array<double, 2>> point_inside(const Polygon& ring) {
  if (ring.size() < 3) return std::nullopt;
  double lo = ring[0][1], hi = ring[0][1];
  for (const auto& p : ring) lo = std::min(lo, p[1]), hi = std::max(hi, p[1]);
  const double y = (lo + hi) / 2;
  std::vector<double> xs;
  for (size_t i = 0; i < ring.size(); ++i) {
    const auto& a = ring[i];
    const auto& b = ring[(i + 1) % ring.size()];
    if ((a[1] <= y) != (b[1] <= y)) xs.push_back(a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
  }
  if (xs.size() < 2) return std::nullopt;
  std::sort(xs.begin(), xs.end());
  return std::array<double, 2>{(xs[0] + xs[1]) / 2, y};
}

bool is_simple(const Polygon& polygon) {
  if (polygon.size() < 3 || polygon_area(polygon) <= kEps) return false;
  return !first_crossing(polygon);
}

std::optional<std::vector<Rect>> as_rectangles(const Polygon& polygon) {
  const size_t n = polygon.size();
  std::vector<double> ys;
  for (size_t i = 0; i < n; ++i) {
    const auto& a = polygon[i];
    const auto& b = polygon[(i + 1) % n];
    if (std::fabs(a[0] - b[0]) > kEps && std::fabs(a[1] - b[1]) > kEps) return std::nullopt;
    ys.push_back(a[1]);
  }
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  std::vector<Rect> rects;
  for (size_t k = 0; k + 1 < ys.size(); ++k) {
    // Across the band's middle, the vertical edges pair up into spans inside the polygon.
    const double mid = (ys[k] + ys[k + 1]) / 2;
    std::vector<double> xs;
    for (size_t i = 0; i < n; ++i) {
      const auto& a = polygon[i];
      const auto& b = polygon[(i + 1) % n];
      if ((a[1] > mid) != (b[1] > mid)) xs.push_back(a[0]);
    }
    std::sort(xs.begin(), xs.end());
    for (size_t i = 0; i + 1 < xs.size(); i += 2)
      rects.push_back({xs[i], ys[k], xs[i + 1] - xs[i], ys[k + 1] - ys[k]});
  }
  return rects;
}

bool segment_meets(const std::array<double, 2>& a, const std::array<double, 2>& b, const Rect& r,
                   double inset) {
  const double x0 = r.x + inset, x1 = r.right() - inset, y0 = r.y + inset, y1 = r.top() - inset;
  if (x0 > x1 || y0 > y1 || (inset > 0 && (x0 == x1 || y0 == y1))) return false;
  double t0 = 0, t1 = 1;
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  for (const auto& [p, q] : {std::pair{-dx, a[0] - x0}, std::pair{dx, x1 - a[0]},
                             std::pair{-dy, a[1] - y0}, std::pair{dy, y1 - a[1]}}) {
    if (p == 0) {
      if (q < 0) return false;
      continue;
    }
    const double t = q / p;
    if (p < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

namespace {

// Whether the segment a-b passes through the open rectangle: touching a side is not passing
// through.
bool passes_through(const std::array<double, 2>& a, const std::array<double, 2>& b, const Rect& r) {
  return segment_meets(a, b, r, 1e-7);
}

}  // namespace

double distance_to_segment(const std::array<double, 2>& p, const std::array<double, 2>& a,
                           const std::array<double, 2>& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], length2 = dx * dx + dy * dy;
  const double t =
      length2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
}

double distance_to_edges(const Polygon& p, double x, double y) {
  double nearest = 1e300;
  for (size_t i = 0; i < p.size(); ++i)
    nearest = std::min(nearest, distance_to_segment({x, y}, p[i], p[(i + 1) % p.size()]));
  return nearest;
}

Crossing crossing(const Rect& r, const Polygon& polygon) {
  for (size_t i = 0; i < polygon.size(); ++i)
    if (passes_through(polygon[i], polygon[(i + 1) % polygon.size()], r)) return Crossing::boundary;
  return contains(polygon, r.x + r.w / 2, r.y + r.h / 2) ? Crossing::inside : Crossing::outside;
}

PolygonIndex::PolygonIndex(const Polygon& polygon) : polygon_(polygon) {
  const size_t n = polygon.size();
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& p : polygon)
    x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]), x1 = std::max(x1, p[0]),
    y1 = std::max(y1, p[1]);
  bounds_ = n ? Rect{x0, y0, x1 - x0, y1 - y0} : Rect{};
  // About four edges a cell.
  const auto side =
      static_cast<size_t>(std::clamp(std::sqrt(static_cast<double>(n) / 4), 1.0, 512.0));
  columns_ = rows_ = side;
  cells_.resize(columns_ * rows_);
  bands_.resize(rows_);
  for (size_t i = 0; i < n; ++i) {
    const auto& a = polygon[i];
    const auto& b = polygon[(i + 1) % n];
    const size_t c0 = column_of(std::min(a[0], b[0])), c1 = column_of(std::max(a[0], b[0]));
    const size_t r0 = row_of(std::min(a[1], b[1])), r1 = row_of(std::max(a[1], b[1]));
    for (size_t r = r0; r <= r1; ++r) {
      bands_[r].push_back(static_cast<uint32_t>(i));
      for (size_t c = c0; c <= c1; ++c)
        cells_[r * columns_ + c].push_back(static_cast<uint32_t>(i));
    }
  }
}

size_t PolygonIndex::column_of(double x) const {
  if (bounds_.w <= 0) return 0;
  return std::min(columns_ - 1,
                  static_cast<size_t>(
                      std::max(0.0, (x - bounds_.x) / bounds_.w * static_cast<double>(columns_))));
}

size_t PolygonIndex::row_of(double y) const {
  if (bounds_.h <= 0) return 0;
  return std::min(rows_ - 1, static_cast<size_t>(std::max(
                                 0.0, (y - bounds_.y) / bounds_.h * static_cast<double>(rows_))));
}

bool PolygonIndex::misses_bounds(const Rect& r) const {
  return polygon_.empty() || r.right() < bounds_.x || r.x > bounds_.right() ||
         r.top() < bounds_.y || r.y > bounds_.top();
}

Crossing PolygonIndex::crossing(const Rect& r) const {
  const size_t n = polygon_.size();
  if (misses_bounds(r)) return Crossing::outside;
  for (size_t row = row_of(r.y); row <= row_of(r.top()); ++row)
    for (size_t col = column_of(r.x); col <= column_of(r.right()); ++col)
      for (const uint32_t i : cells_[row * columns_ + col])
        if (passes_through(polygon_[i], polygon_[(i + 1) % n], r)) return Crossing::boundary;
  return contains(r.x + r.w / 2, r.y + r.h / 2) ? Crossing::inside : Crossing::outside;
}

bool PolygonIndex::contains(double x, double y) const {
  const size_t n = polygon_.size();
  if (n == 0 || y < bounds_.y || y > bounds_.top() || x > bounds_.right()) return false;
  return contains_as_polygon(x, y);
}

std::vector<uint32_t> PolygonIndex::edges_near(const Rect& r) const {
  std::vector<uint32_t> edges;
  if (misses_bounds(r)) return edges;
  for (size_t row = row_of(r.y); row <= row_of(r.top()); ++row)
    for (size_t col = column_of(r.x); col <= column_of(r.right()); ++col)
      edges.insert(edges.end(), cells_[row * columns_ + col].begin(),
                   cells_[row * columns_ + col].end());
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

bool PolygonIndex::contains_as_polygon(double x, double y) const {
  const size_t n = polygon_.size();
  if (n == 0 || bands_.empty()) return false;
  // The even-odd rule of curdle::contains, over the edges of y's band alone: an edge straddling
  // y has its lower end's row at or below y's and its upper end's at or above (row_of rises
  // with y), so it is filed under y's row.
  bool in = false;
  for (const uint32_t i : bands_[row_of(y)]) {
    const auto& a = polygon_[(i + 1) % n];
    const auto& b = polygon_[i];
    if ((a[1] > y) != (b[1] > y) && x < (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
  }
  return in;
}

}  // namespace curdle
