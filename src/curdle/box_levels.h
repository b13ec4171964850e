// Boxes aligned to a lattice, from the finest up: at level 0 the cells themselves, at level j
// boxes of base^j cells a side, box i covering cells [i base^j, (i + 1) base^j) along each axis.
// Each level's occupied boxes come from the level below (a box holds a cell when one of its
// base^E boxes does), so a whole pyramid costs about one pass over the cells. Box counting a
// picture (measure.h), a fitted curd's occupied cells (fit.h) and share-weighted box counts
// (extinction.h) all read it.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "curdle/box.h"

namespace curdle {

struct BoxLevel {
  int index = 0;                          // j
  int64_t side = 1;                       // base^j cells a side
  std::array<int64_t, 3> first{0, 0, 0};  // index of the first box along each axis
  std::array<int64_t, 3> count{1, 1, 1};  // boxes along each axis
  std::vector<bool> occupied;             // x fastest, then y, then z

  // Where `box` (its index along each axis, as `first` counts) sits in `occupied`.
  size_t at(const std::array<int64_t, 3>& box) const {
    return static_cast<size_t>(((box[2] - first[2]) * count[1] + (box[1] - first[1])) * count[0] +
                               (box[0] - first[0]));
  }
};

// Calls visit(at) for every occupied box of the level, `at` its index along each axis.
template <class F>
void for_each_occupied(const BoxLevel& level, F&& visit) {
  size_t i = 0;
  for (int64_t z = 0; z < level.count[2]; ++z)
    for (int64_t y = 0; y < level.count[1]; ++y)
      for (int64_t x = 0; x < level.count[0]; ++x, ++i)
        if (level.occupied[i])
          visit(std::array<int64_t, 3>{level.first[0] + x, level.first[1] + y, level.first[2] + z});
}

// Calls visit for levels 0..levels. `cells` covers `box` (x fastest, then y, then z; cell
// coordinates are box.origin + offset); axes beyond `dimension` must have size 1.
void for_each_box_level(int base, int dimension, const Box& box, std::vector<bool> cells,
                        int levels, const std::function<void(const BoxLevel&)>& visit);

}  // namespace curdle
