// Whether a polygon's edges cross or touch one another, and where.
#pragma once

#include <array>
#include <optional>

#include "layout/geometry.h"

namespace curdle {

// Where two edges that are not neighbours cross or touch (within 1e-9 mm) first found, or
// nullopt for a simple polygon. Each edge is filed under the cells of a grid it passes through,
// not every cell its box covers, and only edges that share a cell are compared: a surveyed
// outline of 100,000 corners, or a star of 10,000 long spikes meeting near its middle, is
// checked in well under a second.
std::optional<std::array<double, 2>> first_crossing(const Polygon& polygon);

}  // namespace curdle
