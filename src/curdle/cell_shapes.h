// Cells seen through a view, by shape: along each axis the part of a cell inside the view is
// the whole cell or a cut at one end, so the cells of a level (and the children of a cell) fall
// into at most 3^E classes. Expectations summed per class are exact at any crop.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace curdle {

// The part of a cell inside the view along one axis, in finest cells from the cell's start, and
// along every axis (unused axes hold {0, 1}).
using CellSpan = std::pair<int64_t, int64_t>;
using CellShape = std::array<CellSpan, 3>;

// Cells of side `side` meeting [lo, hi) along one axis, by the part of them inside.
std::map<CellSpan, uint64_t> spans_meeting(int64_t lo, int64_t hi, int64_t side);

// The children of a cell of side `side` whose inside part is `span`, by their inside parts.
std::map<CellSpan, uint64_t> child_spans(const CellSpan& span, int64_t side, int base);

// Cartesian product of per-axis classes: shapes with how many cells (or children) have each.
std::vector<std::pair<CellShape, uint64_t>> shapes(
    const std::array<std::map<CellSpan, uint64_t>, 3>& axes, int dimension);

}  // namespace curdle
