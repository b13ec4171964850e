// The geometry of zones (layout.h: Zone) and other polygons in layout millimetres.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "layout/layout.h"
#include "layout/polygon_crossing.h"

namespace curdle {

Polygon rect_polygon(const Rect& r);

// Whether (x, y) lies inside the polygon (even-odd; a point on an edge may go either way).
bool contains(const Polygon& polygon, double x, double y);

// The polygon's area, mm² (any orientation).
double polygon_area(const Polygon& polygon);
// The signed area: positive for a counter-clockwise ring (an outline's outer ring).
double signed_area(const Polygon& polygon);
// A point inside a ring: the middle of the first span a line across its middle height cuts
// through it. None for a degenerate ring.
std::optional<std::array<double, 2>> point_inside(const Polygon& ring);

// Whether no two edges of the polygon cross or touch, other than neighbours at their vertex.
bool is_simple(const Polygon& polygon);

// Whether the segment a-b meets the rectangle shrunk by `inset` on every side (Liang and
// Barsky's clipping): 0 the closed rectangle, a little more its open inside.
bool segment_meets(const std::array<double, 2>& a, const std::array<double, 2>& b, const Rect& r,
                   double inset = 0);

// The distance from (x, y) to the polygon's nearest edge, inside or out.
double distance_to_edges(const Polygon& polygon, double x, double y);
// The distance from p to the segment a-b (to a when they coincide).
double distance_to_segment(const std::array<double, 2>& p, const std::array<double, 2>& a,
                           const std::array<double, 2>& b);

// Where a rectangle lies against a polygon: wholly inside, wholly outside, or crossed by one of
// its edges (an edge along the rectangle's side does not cross it).
enum class Crossing { inside, outside, boundary };
Crossing crossing(const Rect& r, const Polygon& polygon);

// A polygon's edges bucketed on a grid, so that `crossing` and `contains` look only at the
// edges near the rectangle or point: a surveyed outline of 8,000 corners tested against every
// one of 6,600 slabs took a second a laying. It keeps its own copy of the polygon.
class PolygonIndex {
 public:
  explicit PolygonIndex(const Polygon& polygon);
  Crossing crossing(const Rect& r) const;
  bool contains(double x, double y) const;
  // curdle::contains(polygon, x, y) to the bit: its even-odd rule over y's band of edges alone
  // (an edge that straddles y is always in it), with no shortcut of its own.
  bool contains_as_polygon(double x, double y) const;
  // The edges (edge i runs from corner i to i + 1) filed under the cells the rectangle covers,
  // each once, in order: every edge that meets it or starts in it, and others near it.
  std::vector<uint32_t> edges_near(const Rect& r) const;
  const Polygon& polygon() const { return polygon_; }

 private:
  Polygon polygon_;
  Rect bounds_;
  size_t columns_ = 1, rows_ = 1;
  std::vector<std::vector<uint32_t>> cells_;  // edges by cell, row by row
  std::vector<std::vector<uint32_t>> bands_;  // edges by row, for the ray of `contains`
  size_t column_of(double x) const;
  size_t row_of(double y) const;
  bool misses_bounds(const Rect& r) const;  // no edge can meet r, nor start in it
};

// A polygon whose edges all run along x or y as disjoint rectangles (bands between its
// vertices' heights); nullopt when some edge slopes.
std::optional<std::vector<Rect>> as_rectangles(const Polygon& polygon);

}  // namespace curdle
