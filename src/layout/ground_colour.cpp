#include "layout/ground_colour.h"

#include "layout/layout_kind.h"

namespace curdle {

Rgb ground_colour(const Layout& layout) {
  if (layout.kind->ground() == Ground::sheet) return kSheetMetal;
  if (layout.joint > 0) return layout.joint_colour;
  if (layout.combine != Combine::mix || layout.kind->ground() == Ground::paper)
    return Rgb{255, 255, 255};
  const LegendEntry* most = nullptr;
  for (const LegendEntry& e : layout.legend)
    if (!most || e.count > most->count) most = &e;
  return most ? most->colour : Rgb{255, 255, 255};
}

}  // namespace curdle
