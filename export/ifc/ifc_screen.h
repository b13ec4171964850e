// layout.ifc's bodies of a screen's sheets on a building (framed_sheet.h): each sheet's solid
// less its tiles' squares, and each tile a mapped copy of one shape placed round its opening, as
// layout.glb draws it: the thousands of openings cost a placement each, not their corners.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "curdle/palette.h"
#include "export/ifc/ifc_geometry.h"
#include "layout/framed_sheet.h"
#include "layout/layout.h"

namespace curdle {

class IfcScreenSheets {
 public:
  IfcScreenSheets(IfcGeometryWriter& geometry, const Layout& layout) : g_(geometry), l_(layout) {}
  // The body of sheet `sheet` (an index into layout.sheets()), its solid in `colour`.
  int64_t body(size_t sheet, const Rgb& colour);

 private:
  IfcGeometryWriter& g_;
  const Layout& l_;
  FramedScreen screen_;                                // worked out at the first sheet
  std::map<std::vector<int64_t>, int64_t> tile_maps_;  // by shape
};

}  // namespace curdle
