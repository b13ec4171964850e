// A stack of blocks drawn as a plan and an elevation of its voxels, side by side (the blocks
// kind's own record on its layout): each cell of a view in the value it shows, with the blocks
// behind it, the one shown first; captions say which view is which.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "layout/geometry.h"

namespace curdle {

struct BlockViews {
  struct Cell {
    Rect rect;
    uint32_t value = 0;
    std::vector<std::string> elements;  // IDs along the line of sight, the one shown first
    bool plan = false;                  // in the plan: every block lies under one plan cell
  };
  std::vector<Cell> cells;
  std::vector<std::pair<std::string, Rect>> captions;
};

}  // namespace curdle
