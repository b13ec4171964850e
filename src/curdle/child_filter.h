// Which children of a cell meet the generated box: one bit per child digit along each axis.
// Generation visits only children inside the box, so that a window costs what it shows.
#pragma once

#include <array>
#include <cstdint>

#include "curdle/box.h"
#include "curdle/cell_index.h"

namespace curdle {

struct ChildFilter {
  std::array<uint64_t, 3> axis{~uint64_t{0}, ~uint64_t{0}, ~uint64_t{0}};
  bool all = true;

  bool allows(const std::array<uint8_t, 3>& digits) const {
    return ((axis[0] >> digits[0]) & (axis[1] >> digits[1]) & (axis[2] >> digits[2]) & 1) != 0;
  }
};

// The filter of the children (at `stage`) of the stage-(stage - 1) cell `parent_index`.
inline ChildFilter children_in_box(const CellIndex& index, const Box& box, int stage,
                                   uint64_t parent_index) {
  ChildFilter f;
  const Lattice& l = index.lattice();
  const Coord parent = index.decode(stage - 1, parent_index);
  const int64_t s = static_cast<int64_t>(l.side_in_cells(stage));
  const uint64_t every = l.base == 64 ? ~uint64_t{0} : (uint64_t{1} << l.base) - 1;
  for (int d = 0; d < l.dimension; ++d) {
    uint64_t mask = 0;
    const int64_t lo = box.origin[d], hi = box.origin[d] + box.size[d];
    for (int delta = 0; delta < l.base; ++delta) {
      const int64_t start = (parent[d] * l.base + delta) * s;
      if (start < hi && start + s > lo) mask |= uint64_t{1} << delta;
    }
    f.axis[d] = mask;
    if (mask != every) f.all = false;
  }
  return f;
}

}  // namespace curdle
