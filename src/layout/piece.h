// A piece as laid: the one reading of an element's geometry that the schedule, the drawings,
// the glTF and the DXF share, so that no two files can describe the same piece differently.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// The piece's extent as laid: its rectangles' bounding box, or its opening's (a circle or a
// merged outline); the nominal element when it has neither.
Rect laid_bounds(const Element& e);

// Whether `part` of a unit round a closed envelope's last corner is the part carried round to
// the strip's start (it lies before the unit's own start).
inline bool carried_round_the_seam(const Element& e, const Rect& part) {
  return part.x < e.nominal.x - 1e-6;
}

// Where the piece is labelled and found on a sheet: its laid extent, but for a unit round a
// closed envelope's last corner, laid in two parts at the strip's two ends, its larger part
// (the box of both would span the strip).
Rect label_bounds(const Element& e);

// Whether the piece is one axis-aligned rectangle (whole, or cut straight at an edge).
bool is_rectangle(const Element& e);

// The piece's outline when it is not one rectangle and not a circle: the union of its
// rectangles (an L-shaped panel cut at a window), or a merged opening. Empty otherwise.
std::vector<Outline> piece_outlines(const Element& e);

// Pieces smaller than their module (cut at an edge or an opening).
uint64_t cut_elements(const Layout& layout);

// What the piece is made of and its colour: a park element's own (a standing object's species
// where the recipe names one, else its type), else its value's (the legend's label is the
// material's name, layout.materials or the curds').
const std::string& piece_material(const Layout& layout, const Element& e);
const Rgb& piece_colour(const Layout& layout, const Element& e);

// What the contractor orders for a standing object (a park's tree, bench), by the curd or state
// that placed it; an empty spec when the recipe gave none.
const PlantingSpec& planting_of(const Layout& layout, const Element& e);
// The tree pit dug for a standing object, centred on it; none when the recipe gave no pit.
std::optional<Rect> tree_pit(const Layout& layout, const Element& e);
// A standing rectangular object's back (a bench's backrest), the edge opposite the way it faces
// (Element::turn): its two ends, mm; nullopt for a round one or anything else.
std::optional<std::array<std::array<double, 2>, 2>> back_edge(const Element& e);

// Keep mode: the stripe of the element each curd present keeps, side by side from the side
// laying starts from, cut to the piece as laid; one part, the whole piece, in mix mode.
struct ColouredRect {
  Rect rect;
  Rgb colour;
};
std::vector<ColouredRect> keep_stripes(const Layout& layout, const Element& e);

// Where each row of the laying order lies (y extent of its elements, mm) and each column (x
// extent), for row and column numbers on drawings.
struct LayingExtents {
  std::map<int64_t, std::pair<double, double>> rows, columns;
};
LayingExtents laying_extents(const Layout& layout);

}  // namespace curdle
