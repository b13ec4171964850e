// The park kind: its keys (park_reader.cpp), its surfaces and objects (park_builder.cpp), and
// what drawings and models need of it.
#include "kinds/park.h"

#include <fmt/format.h>

#include "layout/drawing_sheet.h"
#include "recipe/layout_reader.h"

namespace curdle {

std::string ParkKind::size_line(const Layout& layout) const {
  return fmt::format("{} x {} mm: {} x {} cells of {} x {} mm, {} elements",
                     drawing_mm(layout.width), drawing_mm(layout.height), layout.columns,
                     layout.rows, drawing_mm(layout.module_w), drawing_mm(layout.module_h),
                     layout.elements.size());
}

std::unique_ptr<KindKeys> ParkKind::default_keys() const { return std::make_unique<ParkKeys>(); }

void ParkKind::read_own(reading::TableReader& r, const Design& design, LayoutSpec& spec) const {
  reading::read_park(r, design, spec);
  reading::read_zones(r, design, spec);
  reading::check_park_faces(r, spec);
}

void ParkKind::replace_cells(Layout& layout, const Design& design, const LayoutSpec& spec) const {
  plant(layout, design, spec);
}

}  // namespace curdle
