// A perforated screen's fabrication (the perforation kind's own record on its layout): the
// sheets the surface is cut into, row by row from the origin (one, the whole surface, when no
// sheet size is given), and the stock they are cut from, for the order list.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "layout/geometry.h"

namespace curdle {

struct FabricationSheet {
  std::string id;  // S-R1-C2: row and column of sheets
  Rect area;
  // Its outline when layout.outline cuts it (rings in mm, as union.h lists them); empty: the
  // whole rectangle.
  std::vector<Ring> outline;
  Contour outline_contour;  // the same with the outline's arcs, where it has any and is one piece
  double surface = 0;       // mm² of sheet: the rectangle's, or its outline's
  double open_area = 0;     // share of the sheet's area that is open
  // Openings per tool: "D22.6" for a punch of 22.6 mm, "outline" for merged openings cut
  // along their outline; in order of the tool's name.
  std::vector<std::pair<std::string, uint64_t>> tools;
  // On a building: the façade it stands on, and where that is an arc the sheet is rolled to
  // it: the inside radius of the bend, and the blank's length per mm of the outer face (the
  // blank is developed at mid-thickness). Flat: radius 0, the blank the sheet.
  std::string facade;
  double bend_radius = 0;
  double developed = 1;
};

struct SheetFabrication {
  std::vector<FabricationSheet> sheets;
  std::array<double, 2> stock{0, 0};  // layout.sheet_size, or the whole surface
  std::string material;               // layout.sheet_material
};

}  // namespace curdle
