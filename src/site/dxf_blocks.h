// A DXF's blocks as it defines and inserts them, and their placing: the model's shapes and every
// block it inserts (base point, scale, rotation, arrays, nesting, mirrors), in the plan.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "site/drawing.h"

namespace curdle::site {

struct Insert {
  std::string block, layer, handle;
  double x = 0, y = 0, sx = 1, sy = 1, angle = 0;  // angle in degrees, all in the OCS
  int64_t columns = 1, rows = 1;
  double column_spacing = 0, row_spacing = 0;
  double ocs_x = 1;  // -1: drawn from below (extrusion 0, 0, -1), x mirrored into the plan
};

struct Block {
  double base_x = 0, base_y = 0;
  std::vector<Shape> shapes;
  std::vector<Insert> inserts;
};

// Block placements a drawing may ask for, counting each array cell: an empty block inserted in
// arrays of arrays places nothing but would be visited without end.
inline constexpr size_t kMostPlacements = 1000000;

// Places the model's shapes (the block "") and the blocks it inserts, nested, into `drawing`:
// a block's shapes on layer 0 take the INSERT's layer, and each shape says its top INSERT;
// arcs stretched unevenly are flattened within `tolerance` (drawing units). Returns the names
// of blocks inserted but never defined. InputError naming `file` for a block nested more than
// 16 deep, or for more shapes, vertices or placements than a site drawing holds.
std::set<std::string> place_blocks(const std::map<std::string, Block>& blocks,
                                   const std::string& file, double tolerance, Drawing& drawing);

}  // namespace curdle::site
