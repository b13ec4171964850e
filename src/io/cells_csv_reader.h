// cells.csv read back (the file write_cells_csv writes, or one made by hand the same way): its
// curds and, for each, the cells where it survived over the box the rows cover. Every input is
// hostile: the header must name the axes, `value` and the curds; every row must be whole
// numbers, one per column, bits 0 or 1 that make its value; every cell of the box exactly once.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "curdle/box.h"

namespace curdle {

struct CellsTable {
  int dimension = 0;  // 1, 2 or 3: the axes the header names
  Box box;            // from the least coordinates to the greatest
  std::vector<std::string> curds;
  std::vector<std::vector<bool>> cells;  // per curd, over `box`, x fastest, then y, then z
};

// Throws InputError naming the line and what is wrong, and ResourceLimitError when the box
// holds over `max_cells` cells.
CellsTable parse_cells_csv(std::string_view text, uint64_t max_cells);

}  // namespace curdle
