// The perforated-sheet kind: its keys (perforation_reader.cpp), its openings and fabrication
// sheets (perforation_builder.cpp), and what drawings and models need of it.
#include "kinds/perforation.h"

#include <fmt/format.h>

#include "layout/drawing_sheet.h"

namespace curdle {

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

std::vector<std::string> PerforationKind::own_keys() const {
  return {"holes",      "thickness", "min_diameter", "min_bridge", "edge_margin",    "fix",
          "sheet_size", "punches",   "open_area",    "outline",    "sheet_material", "building"};
}

std::unique_ptr<KindKeys> PerforationKind::default_keys() const {
  return std::make_unique<PerforationKeys>();
}

void PerforationKind::read_own(reading::TableReader& r, const Design& design,
                               LayoutSpec& spec) const {
  reading::read_perforation(r, design, spec);
  if (r.get("building")) reading::read_perforated_building(r, spec);
}

Layout PerforationKind::build(const Design& design, const CurdField& field, const Box& view,
                              const LayoutSpec& spec) const {
  Layout layout = SurfaceKind::build(design, field, view, spec);
  if (const auto& envelope = spec.own<PerforationKeys>().envelope) {
    layout.envelope.emplace().frames = envelope->facades;
    layout.envelope->closed = envelope->closed;
    if (envelope->closed)  // unlike a façade's bricks, the cells are not laid as a ring
      layout.notes.push_back(
          "round the plan the screen's field is laid from its start corner, its seam where the "
          "strip's end meets its start (layout.building.start moves it)");
  }
  return layout;
}

void PerforationKind::replace_cells(Layout& layout, const Design& design,
                                    const LayoutSpec& spec) const {
  perforate(layout, design, spec);
}

const Envelope* PerforationKind::envelope(const LayoutSpec& spec) const {
  const std::optional<Envelope>& e = spec.own<PerforationKeys>().envelope;
  return e ? &*e : nullptr;
}

}  // namespace curdle
