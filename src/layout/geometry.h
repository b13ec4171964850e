// The plane shapes layouts are made of, in millimetres: rectangles, circles, rings, polygons and
// contours with arcs, and the few operations on rectangles every kind uses.
#pragma once

#include <array>
#include <vector>

namespace curdle {

struct Rect {
  double x = 0, y = 0, w = 0, h = 0;
  double area() const { return w * h; }
  double right() const { return x + w; }
  double top() const { return y + h; }
  bool operator==(const Rect&) const = default;
};

// Rectangles that overlap by more than a rounding error (1e-6 mm). Inline: the installer's
// labels ask it millions of times.
inline bool overlaps(const Rect& a, const Rect& b) {
  constexpr double eps = 1e-6;
  return a.x < b.right() - eps && b.x < a.right() - eps && a.y < b.top() - eps &&
         b.y < a.top() - eps;
}
// a minus the union of `holes`, as disjoint rectangles (all edges are axis-aligned).
std::vector<Rect> subtract(const Rect& a, const std::vector<Rect>& holes);
// The part of r on the surface [0, width] x [0, height] (empty: zero width or height).
Rect clip(const Rect& r, double width, double height);
// A w x h rectangle centred on (cx, cy).
inline Rect centred_on(double cx, double cy, double w, double h) {
  return {cx - w / 2, cy - h / 2, w, h};
}

struct Circle {
  double cx = 0, cy = 0, d = 0;
  double area() const { return 3.14159265358979323846 * d * d / 4; }
};
using Ring =
    std::vector<std::array<double, 2>>;  // closed implicitly; outer rings counter-clockwise

// An opening's outline: outer rings and the islands inside them, with its exact-arithmetic area.
struct Outline {
  std::vector<Ring> rings;
  double area = 0;
  // A merged opening: the round openings whose union the rings are (polygonised), so that a
  // drawing can show its arcs as arcs. Empty for any other outline.
  std::vector<Circle> circles;
};

using Polygon = std::vector<std::array<double, 2>>;  // simple, closed implicitly

// A boundary whose edges are straight or circular arcs (contour.h): each vertex with the bulge
// of the edge to the next, as CAD writes it. Outlines and zones keep their arcs in one, beside
// the polygon of chords that pieces are cut along.
struct ContourVertex {
  double x = 0, y = 0;
  double bulge = 0;  // tan(θ / 4) of the edge's arc to the next vertex; 0 straight
  bool operator==(const ContourVertex&) const = default;
};
using Contour = std::vector<ContourVertex>;  // closed implicitly

}  // namespace curdle
