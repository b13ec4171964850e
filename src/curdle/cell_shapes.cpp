#include "curdle/cell_shapes.h"

#include <algorithm>

#include "curdle/box.h"

namespace curdle {

// Stage cells of side `side` meeting [lo, hi) along one axis, by the part of them inside.
std::map<CellSpan, uint64_t> spans_meeting(int64_t lo, int64_t hi, int64_t side) {
  std::map<CellSpan, uint64_t> out;
  const int64_t first = floor_div(lo, side), last = floor_div(hi - 1, side);
  for (const int64_t i : {first, last}) {
    out[{std::max(lo, i * side) - i * side, std::min(hi, (i + 1) * side) - i * side}] += 1;
    if (first == last) break;
  }
  if (last - first > 1) out[{0, side}] += static_cast<uint64_t>(last - first - 1);
  return out;
}

// The children of a cell of side `side` whose inside part is `span`, by their inside parts.
std::map<CellSpan, uint64_t> child_spans(const CellSpan& span, int64_t side, int base) {
  std::map<CellSpan, uint64_t> out;
  const int64_t child = side / base;
  for (int c = 0; c < base; ++c) {
    const int64_t lo = std::max(span.first, c * child), hi = std::min(span.second, (c + 1) * child);
    if (hi > lo) out[{lo - c * child, hi - c * child}] += 1;
  }
  return out;
}

// Cartesian product of per-axis classes: shapes with how many cells (or children) have each.
std::vector<std::pair<CellShape, uint64_t>> shapes(
    const std::array<std::map<CellSpan, uint64_t>, 3>& axes, int dimension) {
  std::vector<std::pair<CellShape, uint64_t>> out{
      {CellShape{CellSpan{0, 1}, CellSpan{0, 1}, CellSpan{0, 1}}, 1}};
  for (int d = 0; d < dimension; ++d) {
    std::vector<std::pair<CellShape, uint64_t>> next;
    for (const auto& [shape, n] : out)
      for (const auto& [span, m] : axes[d]) {
        CellShape s = shape;
        s[d] = span;
        next.push_back({s, n * m});
      }
    out = std::move(next);
  }
  return out;
}

}  // namespace curdle
