// cells.csv read back (the file write_cells_csv writes, or one made by hand the same way): its
// curds and, for each, the cells where it survived over the box the rows cover. Every input is
// hostile: the header must name the axes, `value` and the curds; every row must be whole
// numbers, one per column, bits 0 or 1 that make its value; every cell of the box exactly once.
// A Markov curd's column names each cell's state ("dead" or a living state's name); its state's
// number is the value's bits at the curd's planes (markov.h), which every row must agree with.
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
  // Per curd: a Markov curd's living states by number (1, 2, ...; a number no cell has is
  // named ""), empty for a plain curd; and each cell's state (a plain curd's 0 or 1).
  std::vector<std::vector<std::string>> states;
  std::vector<std::vector<uint8_t>> state_cells;
  bool markov(size_t curd) const { return !states[curd].empty(); }
};

// Throws InputError naming the line and what is wrong, and ResourceLimitError when the box
// holds over `max_cells` cells.
CellsTable parse_cells_csv(std::string_view text, uint64_t max_cells);

}  // namespace curdle
