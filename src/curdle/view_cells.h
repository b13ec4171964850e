// Where each cell of a view lies in a field's finest bitsets, row by row: the index of cell
// (x, y, z) is a sum of one entry per axis, so that a row is read with one addition a cell.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "curdle/curd.h"

namespace curdle {

class ViewCells {
 public:
  ViewCells(const CurdField& field, const Box& view);

  // The part of the index shared by the row (y, z), counted from the view's origin.
  uint64_t row(int64_t y, int64_t z) const { return offset_[1][y] + offset_[2][z]; }
  // The finest index of cell x of a row (x counted from the view's origin).
  uint64_t at(uint64_t row, int64_t x) const { return offset_[0][x] + row; }

 private:
  std::array<std::vector<uint64_t>, 3> offset_;
};

}  // namespace curdle
