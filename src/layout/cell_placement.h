// Where a layout puts each lattice cell, as the affine map (with a bond's course shifts) that
// density fields in millimetres are read through (curdle/density.h).
#pragma once

#include <array>

#include "curdle/density.h"
#include "layout/layout.h"

namespace curdle {

// The map from finest cells to millimetres for `spec` laid from `view`: a cell's centre goes
// to the centre of its element as laid (before any cut); the kind says (a rhythm's bays take
// their widths from the values, so a line keeps cells as its units; voxels are storeys).
CellPlacement cell_placement(const LayoutSpec& spec, const Box& view);
// The same for a grid of modules and joints (the kinds' default).
CellPlacement grid_cell_placement(const LayoutSpec& spec, const Box& view);

// The surface `spec` covers when laid from `view`, mm: its size, or what the cells fill.
std::array<double, 2> surface_extent(const LayoutSpec& spec, const Box& view);

}  // namespace curdle
