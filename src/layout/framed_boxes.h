// Pieces of a building's strip placed in 3-D through its frames (layout/surface_frame.h): a
// rectangle of the strip, `inward0` to `inward1` mm behind the outer face, as boxes in the
// building (one per frame it lies on; along an arc, one per chord of at most `longest` mm, and
// where its units are bent to the arc, facets within 0.25 mm of it).
// The 3-D writers place a unit box by each (a corner unit laid whole as one prism instead,
// framed_corner.h); they learn nothing of buildings.
#pragma once

#include <array>
#include <vector>

#include "layout/layout.h"

namespace curdle {

struct FramedBox {
  BuildingPoint centre;                      // mm, x east, y north, z up
  std::array<double, 2> along;               // the box's length direction in plan (unit vector)
  double length = 0, height = 0, depth = 0;  // mm: along, up, into the wall
};

std::vector<FramedBox> framed_boxes(const Layout& layout, const Rect& strip_rect, double inward0,
                                    double inward1, double longest = 1e300);

// The backing behind the strip (the mortar the joints show), `set_back` mm behind the outer face
// to `depth`: as framed_boxes, but each face's stopped short of an outer corner far enough that
// its end lies `set_back` behind the other face as well, not flush with it.
std::vector<FramedBox> framed_backing(const Layout& layout, const Rect& strip_rect, double set_back,
                                      double depth, double longest);

// How far behind the outer face a piece runs, mm: a unit from the face to its depth (a header
// by its length), a fin standing off the face from its thickness in front of it (negative) to
// the face.
std::array<double, 2> framed_depth(const Layout& layout, const Element& e);

// A piece's box on the strip, a unit round the closing corner in one piece: its part at the
// strip's start taken on past the end (x + w may pass the strip's length).
Rect framed_strip_bounds(const Layout& layout, const Element& e);

// Where a piece of the strip lies in the building: the middle of its laid outer face (a fin's
// edge standing off the wall; a unit
// that turns the closing corner measured round it; a unit on a curve, on its chord, or on the
// facet that holds it where it is bent to the arc), mm.
BuildingPoint framed_centre(const Layout& layout, const Element& e);

// The façade that holds the middle of a piece's laid outer face.
const SurfaceFrame* framed_facade(const Layout& layout, const Element& e);

}  // namespace curdle
