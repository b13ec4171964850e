// A perforated sheet in 3-D, drawn as tiles: a sheet's round openings come in a few diameters,
// so the glTF draws each as one shared tile (the square of sheet round the opening, with its
// hole) placed at the opening, and cuts only the tiles' squares from the sheet. Triangulating
// the sheet with thousands of round holes was three quarters of a screen's layout.glb, in time
// and in bytes. A merged opening of one ring is a tile too, in its box: the same circles merge
// the same way in every cell, so a screen has a few such shapes however many openings. An
// opening whose square (or box) would touch another's or the sheet's edge stays a hole of the
// sheet itself, so that the solid is the same either way.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "layout/layout.h"

namespace curdle {

struct SheetTiles {
  std::vector<Ring> holes;    // cut from the sheet, with walls: the openings not drawn as tiles
  std::vector<Ring> squares;  // cut from the sheet without walls: the tiles fill them
  std::vector<size_t> tiled;  // indices in layout.elements of the openings drawn as tiles
};

// Every ring runs clockwise (material on its left, the sheet round it). `sheet` is the
// sheet's own outline (its outer rings and the islands cut from it).
SheetTiles sheet_tiles(const Layout& layout, const std::vector<Ring>& sheet);

// The tile of a round opening of diameter `d` centred on (0, 0): the triangles of its face
// between the d x d square and the hole (counter-clockwise), and the hole, clockwise, its
// corners no further than `tolerance` inside the circle and one at each point where the circle
// touches the square, so that the tile meets the sheet along the square's edges.
struct OpeningTile {
  std::vector<std::array<std::array<double, 2>, 3>> triangles;
  Ring hole;
};
OpeningTile opening_tile(double d, double tolerance);

// The tile of a merged opening of one ring: the triangles between its box and its ring, and
// the ring, clockwise, both from the box's lower-left corner. Its box, as outline_box gives it
// ([x0, y0, x1, y1]), is the least round the ring grown by kTileMargin.
inline constexpr double kTileMargin = 0.01;  // mm
OpeningTile outline_tile(const Ring& ring);
// Its ring alone, as outline_tile gives it (no triangles: what tells two tiles apart).
Ring outline_tile_hole(const Ring& ring);
std::array<double, 4> outline_box(const Ring& ring);

}  // namespace curdle
