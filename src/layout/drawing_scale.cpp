#include "layout/drawing_scale.h"

#include "layout/drawing_sheet.h"
#include "layout/layout_kind.h"

namespace curdle {

double drawing_scale(const Layout& layout) {
  if (layout.drawing.scale > 0) return layout.drawing.scale;
  const auto sheet = paper_sheet(layout.drawing.paper).value_or(*paper_sheet("A3"));
  return fit_to_sheet(layout.width, layout.height, sheet).scale;
}

Layout layout_extent(const LayoutSpec& spec, const Box& view) {
  Layout outline;
  outline.kind = spec.kind;
  outline.drawing = spec.drawing;
  const auto extent = spec.kind->drawing_extent(spec, view);
  outline.width = extent[0];
  outline.height = extent[1];
  return outline;
}

}  // namespace curdle
