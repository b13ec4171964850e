// Laying patterns beyond the grid: herringbone at 90° and 45°, basketweave and hexagons. Each
// pattern is a set of units (polygons, in mm from the origin corner, x along the first row and
// y up the rows) and the rule that gives each unit its lattice cell:
//
//   herringbone     one cell per unit: each step of the zig-zag course (a unit along it and
//                   the unit standing on its end) is a column, and the course's two units are
//                   two rows, so that a cell is a square of about a unit's area; at 45° the
//                   courses run along x, at 90° they climb at 45°.
//   basketweave     one cell per square of n units, all n laid in its value: the square is what
//                   the eye reads in basketweave, and a curd's cluster stays whole squares.
//   hexagon         one cell per hexagon: rows of hexagons (pointy top) or columns (flat top),
//                   every other one moved half a hexagon along.
//
// Units are laid with `joint` between them all round; the unit's size is the tile's:
// herringbone and basketweave take a tile whose length is n widths and n - 1 joints (n = 2
// for herringbone), a hexagon a square tile whose side is its width across the flats.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// The recipe's name of each pattern (layout.pattern), and back.
std::string_view pattern_name(LayingPattern pattern);
std::optional<LayingPattern> pattern_named(std::string_view name);

struct PatternUnit {
  Ring ring;                    // counter-clockwise, mm in the pattern's own frame
  int64_t column = 0, row = 0;  // the cell it takes, from (0, 0)
  int part = 0;                 // basketweave: 1..n within its square; 0 otherwise
  double turn = 0;              // its long side from x, degrees (hexagons: a flat side)
};

// How many units of a basketweave square, or 0 where the tile does not make one: its length
// is n widths and n - 1 joints, n from 2 to 4 (to half a millimetre).
int basketweave_units(double length, double width, double joint);

// The most units a pattern may lay (with the border it is generated over): 4 million, 80,000 m²
// of 200 x 100 mm blocks, about 600 MB while they are laid.
inline constexpr uint64_t kMaxPatternUnits = uint64_t{1} << 22;

// Every unit of the pattern that meets [0, width] x [0, height], with its cell counted from the
// least column and row any such unit takes. Units are whole: the caller cuts them to the surface.
// ResourceLimitError above kMaxPatternUnits.
std::vector<PatternUnit> pattern_units(LayingPattern pattern, double length, double width,
                                       double joint, double surface_w, double surface_h);

// How far apart the pattern's cells are along x and y (a herringbone's at 90° along its own
// diagonal axes), mm: what a lattice cell covers on the surface.
std::array<double, 2> pattern_cell_pitch(LayingPattern pattern, double length, double width,
                                         double joint);

// The cells those units take: one past the greatest column and row.
std::array<int64_t, 2> pattern_cells(const std::vector<PatternUnit>& units);

}  // namespace curdle
