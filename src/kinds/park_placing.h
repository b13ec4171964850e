// Where a park's objects stand within their cells: each cell draws its own positions from a
// stream of its own (so trees do not stand on a grid, and a cell places them alike in any
// window of the field), and a bench turns to face what it is meant to face.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// Four numbers in [0, 1) for the `attempt`-th placing of curd member `member` in field cell
// (cell_x, cell_y): Philox4x32-10 under a key of its own made from the seed, so that the
// curds' survival draws (random_stream.h) are not reused. The counter is the cell's
// coordinates (their low 32 bits), the member and the attempt.
std::array<double, 4> placing_draws(uint64_t seed, int64_t cell_x, int64_t cell_y, uint32_t member,
                                    uint32_t attempt);

// The bearing (degrees clockwise from north, +y: 0, 90, 180 or 270) from `from` towards the
// nearest of `targets`, square to the grid; nullopt when there are none. A point inside a
// target looks towards that target's far side along the axis it is closest to leaving by.
std::optional<int> bearing_towards(const std::array<double, 2>& from,
                                   const std::vector<Rect>& targets);

// The same towards a polygon (a zone): towards its nearest edge from outside, its centroid's
// side from inside.
std::optional<int> bearing_towards(const std::array<double, 2>& from, const Polygon& zone);

}  // namespace curdle
