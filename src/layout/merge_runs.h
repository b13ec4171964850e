// Rectangles of equal value merged from a grid: what keeps a 1000 x 1000 layout's drawing small
// and turns a mask image's dark pixels into openings.
#pragma once

#include <cstdint>
#include <vector>

namespace curdle {

// Rectangles of equal value merged from a grid (rows x columns, -1: not merged), as
// {row0, column0, row1, column1, value}, inclusive. Greedy: runs along rows, then runs that
// repeat in the next rows (unless `across_rows` is false: rows that do not line up, as in a
// bond, merge only along themselves).
struct GridRect {
  int64_t row0, column0, row1, column1;
  int value;
};
std::vector<GridRect> merge_runs(const std::vector<int>& grid, int64_t rows, int64_t columns,
                                 bool across_rows = true);

}  // namespace curdle
