// Where a surface needs an edging: the stretches of a piece's edge that no piece of the same
// material lies against (the edge to another material, to the site's edge or to a hole), so
// that the contractor can order edging by the metre per material.
#pragma once

#include <cstdint>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// A piece's boundary, with what it is made of: pieces of one group join without an edging.
struct EdgedPiece {
  std::vector<Ring> rings;  // its outer rings and islands, either orientation
  uint32_t group = 0;
};

// The rings of a laid piece: its rectangles (each a ring; those of one piece join), or its
// outline's rings.
std::vector<Ring> piece_rings(const Element& e);

// Per piece, the length of its boundary where no other piece of its group lies against it, mm.
// Pieces must not overlap; edges are matched along common lines to 0.01 mm.
std::vector<double> unshared_edge_lengths(const std::vector<EdgedPiece>& pieces);

}  // namespace curdle
