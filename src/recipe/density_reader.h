// [curds.density] (curdle/density.h): read with the curd, then placed on the lattice once the
// layout and the window it is laid from are known.
#pragma once

#include <optional>
#include <string>

#include "curdle/density.h"
#include "layout/layout.h"
#include "recipe/toml_reader.h"

namespace curdle::reading {

// What the field's coordinates are in: "millimetres" with a [layout] laid on a grid, "cells"
// without one or for a rhythm (whose bays take their widths from the values).
std::string density_units(const TableReader& top);

// The curd's [curds.density] table; `path` is the curd's ("curds.0").
DensityField read_density(TableReader& curd, const std::string& path, const Lattice& lattice,
                          const std::string& units);

// Puts the field on the lattice: through the layout laid from `view`, or cell for cell; an
// image without a rect covers the surface (or the whole field).
void place_density(DensityField& field, const std::optional<LayoutSpec>& layout, const Box& view,
                   const Box& whole_field);

}  // namespace curdle::reading
