// Unions of round openings, cut as one outline, and of the rectangles of a cut piece: CGAL's
// regularized Boolean operations on circles polygonised within a chord tolerance (CGAL User Manual,
// "2D Regularized Boolean Set-Operations"). CGAL stays inside union.cpp.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "layout/layout.h"
#include "layout/zone.h"

namespace curdle {

// Vertices on the circle such that no chord strays more than `tolerance` inside it.
Ring polygonise(const Circle& circle, double tolerance);

// The union of the circles: one Outline per connected group.
std::vector<Outline> union_of_circles(const std::vector<Circle>& circles, double tolerance);

// The union of axis-aligned rectangles (the pieces of a cut element): one Outline per
// connected part, exact.
std::vector<Outline> union_of_rects(const std::vector<Rect>& rects);

// An outline's parts: its rings as outlines_of lists them, each part's outer ring
// (counter-clockwise) followed by that part's islands (clockwise).
std::vector<Outline> outline_parts(const Outline& outline);

// The parts as one outline (all their rings, their areas summed): a piece in several parts;
// outline_parts splits it again.
Outline joined(const std::vector<Outline>& parts);

// A surface's sloping or curved edges: an outline that is not a union of rectangles, and
// excluded zones that are not. Pieces crossing them are cut along them.
struct PolygonCuts {
  Polygon outline;             // empty: the surface's own rectangle bounds it
  std::vector<Polygon> holes;  // kept free of pieces
  bool empty() const { return outline.empty() && holes.empty(); }
  // Where a piece lies against the outline and each hole, through indexes of their edges that
  // index() builds once the polygons are set (every piece of a surface is tested).
  void index();
  Crossing outline_crossing(const Rect& r) const;
  Crossing hole_crossing(size_t hole, const Rect& r) const;
  // The outline's part within the box (box_clip.h's clip_to_box, through the index once built).
  std::optional<Polygon> outline_near(const Rect& box) const;

 private:
  std::shared_ptr<const PolygonIndex> outline_index_;
  std::vector<std::shared_ptr<const PolygonIndex>> hole_index_;
};

// (the union of `rects`) within the outline and off the holes, exact; one Outline per part.
std::vector<Outline> cut_along(const std::vector<Rect>& rects, const PolygonCuts& cuts);

// A pattern's unit (laying_pattern.h) as laid: within `surface` and the cuts' outline, off the
// rectangular `holes` and the cuts' holes, exact; one Outline per part, none when nothing is
// left.
std::vector<Outline> cut_unit(const Ring& unit, const Rect& surface, const std::vector<Rect>& holes,
                              const PolygonCuts& cuts);

// What of `surface` is not surfaced: beyond the outline, or in a hole.
std::vector<Outline> cut_away(const Rect& surface, const PolygonCuts& cuts);

// The surface less rectangular holes and the outlines cut away (the bed under the pieces).
std::vector<Outline> surfaced(const Rect& surface, const std::vector<Rect>& holes,
                              const std::vector<Outline>& cut_away);

// The part of r inside the outline (a piece cut along a sloping edge), one Outline per part.
std::vector<Outline> clip_outline(const Rect& r, const Outline& outline);

// The area of r inside the outlines (as cut_away gives them).
double area_within(const Rect& r, const std::vector<Outline>& outlines);

// The area of the outlines (a piece as laid) inside the polygon (a zone), exact.
double area_inside(const std::vector<Outline>& outlines, const Polygon& polygon);

}  // namespace curdle
