#include "curdle/view_cells.h"

namespace curdle {

ViewCells::ViewCells(const CurdField& field, const Box& view) {
  const CellIndex& index = field.index;
  const Lattice& l = index.lattice();
  const int64_t side = static_cast<int64_t>(l.root_side());
  // A root's base is linear in its coordinates, so each axis's share of it goes into that
  // axis's table (unsigned sums wrap alike in any order); the first axis's table carries the
  // constant.
  std::array<int64_t, 3> first_root{0, 0, 0};
  for (int d = 0; d < l.dimension; ++d) first_root[d] = floor_div(view.origin[d], side);
  const uint64_t base = index.root_base(first_root);
  for (int d = 0; d < 3; ++d) {
    offset_[d].resize(view.size[d]);
    for (int64_t i = 0; i < view.size[d]; ++i) {
      if (d >= l.dimension) {
        offset_[d][i] = d == 0 ? base : 0;
        continue;
      }
      const int64_t c = view.origin[d] + i;
      Coord r = first_root;
      r[d] = floor_div(c, side);
      offset_[d][i] = index.axis_offset(d, static_cast<uint64_t>(c - r[d] * side)) +
                      (index.root_base(r) - base) + (d == 0 ? base : 0);
    }
  }
}

}  // namespace curdle
