#include "layout/layout_kind.h"

#include <fmt/format.h>

#include "layout/cell_placement.h"
#include "layout/drawing_sheet.h"
#include "layout/layout.h"

namespace curdle {

std::string LayoutKind::size_line(const Layout& layout) const {
  uint64_t cut = 0;
  for (const Element& e : layout.elements) cut += e.cut;
  return fmt::format("{} x {} mm: {} {}s of {} x {} mm, joint {} mm ({} cut)",
                     drawing_mm(layout.width), drawing_mm(layout.height), layout.elements.size(),
                     layout.element_type, drawing_mm(layout.module_w), drawing_mm(layout.module_h),
                     drawing_mm(layout.joint), cut);
}

std::string LayoutKind::laying_line(const Layout& layout) const {
  const std::string corner = layout.origin == Corner::bottom_left    ? "bottom-left"
                             : layout.origin == Corner::bottom_right ? "bottom-right"
                             : layout.origin == Corner::top_left     ? "top-left"
                                                                     : "top-right";
  const std::string bond = layout.envelope && !layout.envelope->bond_name.empty()
                               ? "; " + layout.envelope->bond_name + " bond"
                           : layout.bond == 0.5  ? "; half bond"
                           : layout.bond == 0.25 ? "; quarter bond"
                           : layout.bond > 0     ? "; third bond"
                                                 : "";
  return (layout.centred ? "grid centred, laid from the " + corner + " corner"
                         : "origin " + corner) +
         bond + "; element IDs count rows and columns from it";
}

CellPlacement LayoutKind::cell_placement(const LayoutSpec& spec, const Box& view) const {
  return grid_cell_placement(spec, view);
}

std::array<double, 2> LayoutKind::drawing_extent(const LayoutSpec& spec, const Box& view) const {
  if (spec.size) return *spec.size;
  return {static_cast<double>(view.size[0]) * (spec.module_w + spec.joint),
          static_cast<double>(view.size[1]) * (spec.module_h + spec.joint)};
}

void LayoutSpec::set_kind(const LayoutKind& k) {
  kind = &k;
  keys = OwnKeys(k.default_keys());
}

}  // namespace curdle
