// The park kind: its keys (park_reader.cpp), its surfaces and objects (park_builder.cpp), and
// what drawings and models need of it.
#include "kinds/park.h"

#include <fmt/format.h>

#include "layout/builder.h"
#include "layout/drawing_sheet.h"
#include "recipe/layout_reader.h"

namespace curdle {
namespace {

const reading::SurfaceKeys kSurface{"cell", "area", false, false, false};

}  // namespace

std::string ParkKind::size_line(const Layout& layout) const {
  return fmt::format("{} x {} mm: {} x {} cells of {} x {} mm, {} elements",
                     drawing_mm(layout.width), drawing_mm(layout.height), layout.columns,
                     layout.rows, drawing_mm(layout.module_w), drawing_mm(layout.module_h),
                     layout.elements.size());
}

std::vector<std::string> ParkKind::keys() const {
  std::vector<std::string> keys = reading::surface_keys(kSurface);
  keys.insert(keys.end(), {"elements", "ground", "clearance", "outline"});
  return keys;
}

std::unique_ptr<KindKeys> ParkKind::default_keys() const { return std::make_unique<ParkKeys>(); }

void ParkKind::read(reading::TableReader& r, Design& design, LayoutSpec& spec,
                    bool field_given) const {
  reading::read_surface(r, kSurface, design, spec);
  reading::read_park(r, design, spec);
  reading::size_field(r, kSurface.size_key, design, spec, field_given);
}

Layout ParkKind::build(const Design& design, const CurdField& field, const Box& view,
                       const LayoutSpec& spec) const {
  Layout layout = lay_grid(design, field, view, spec, {});
  count_values(layout, design, spec);
  plant(layout, design, spec);
  return layout;
}

}  // namespace curdle
