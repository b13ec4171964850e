// layout.glb's sheets of a screen on a building: each sheet rolled on its façade (framed_sheet.h)
// and its openings' tiles as children, each shape one mesh.
#pragma once

#include <vector>

#include "export/gltf/gltf_model.h"
#include "layout/layout.h"

namespace curdle {

// A node a sheet, named by its ID, its solid in material `metal` and its tiles its children.
std::vector<int> add_screen_sheets(ModelBuilder& builder, const Layout& layout, int metal);

}  // namespace curdle
