#include "curdle/box_levels.h"

namespace curdle {

void for_each_box_level(int base, int dimension, const Box& box, std::vector<bool> cells,
                        int levels, const std::function<void(const BoxLevel&)>& visit) {
  BoxLevel level;
  for (int d = 0; d < dimension; ++d) level.first[d] = box.origin[d], level.count[d] = box.size[d];
  level.occupied = std::move(cells);
  for (int j = 0;; ++j) {
    visit(level);
    if (j == levels) return;
    BoxLevel up;
    up.index = j + 1;
    up.side = level.side * base;
    for (int d = 0; d < dimension; ++d) {
      up.first[d] = floor_div(level.first[d], base);
      up.count[d] = floor_div(level.first[d] + level.count[d] - 1, base) - up.first[d] + 1;
    }
    up.occupied.assign(static_cast<size_t>(up.count[0] * up.count[1] * up.count[2]), false);
    for_each_occupied(level, [&](std::array<int64_t, 3> at) {
      for (int d = 0; d < dimension; ++d) at[d] = floor_div(at[d], base);
      up.occupied[up.at(at)] = true;
    });
    level = std::move(up);
  }
}

}  // namespace curdle
