// The perforated-sheet kind: its keys (perforation_reader.cpp), its openings and fabrication
// sheets (perforation_builder.cpp), and what drawings and models need of it.
#include "kinds/perforation.h"

#include <fmt/format.h>

#include "layout/builder.h"
#include "layout/drawing_sheet.h"
#include "recipe/layout_reader.h"

namespace curdle {
namespace {

const reading::SurfaceKeys kSurface{"cell", "sheet", true, false, false};

}  // namespace

double PerforationKind::thickness(const LayoutSpec& spec) const {
  return spec.own<PerforationKeys>().thickness;
}

std::string PerforationKind::size_line(const Layout& layout) const {
  return fmt::format("{} x {} mm sheet: {} x {} cells of {} x {} mm", drawing_mm(layout.width),
                     drawing_mm(layout.height), layout.columns, layout.rows,
                     drawing_mm(layout.module_w), drawing_mm(layout.module_h));
}

std::string PerforationKind::laying_line(const Layout& layout) const {
  return fmt::format("sheet {} mm thick, {} openings, open area {:.2f} %, {} rule violations{}",
                     drawing_mm(layout.thickness), layout.elements.size(), 100 * layout.open_area,
                     layout.violations.size(),
                     layout.drops_violations && !layout.violations.empty() ? " (dropped)" : "");
}

std::vector<std::string> PerforationKind::keys() const {
  std::vector<std::string> keys = reading::surface_keys(kSurface);
  keys.insert(keys.end(), {"holes", "thickness", "min_diameter", "min_bridge", "edge_margin", "fix",
                           "chord_tolerance", "sheet_size", "punches", "open_area", "outline"});
  return keys;
}

std::unique_ptr<KindKeys> PerforationKind::default_keys() const {
  return std::make_unique<PerforationKeys>();
}

void PerforationKind::read(reading::TableReader& r, Design& design, LayoutSpec& spec,
                           bool field_given) const {
  reading::read_surface(r, kSurface, design, spec);
  reading::read_perforation(r, design, spec);
  reading::size_field(r, kSurface.size_key, design, spec, field_given);
}

Layout PerforationKind::build(const Design& design, const CurdField& field, const Box& view,
                              const LayoutSpec& spec) const {
  Layout layout = lay_grid(design, field, view, spec, {});
  count_values(layout, design, spec);
  perforate(layout, design, spec);
  return layout;
}

}  // namespace curdle
