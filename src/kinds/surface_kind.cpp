#include "kinds/surface_kind.h"

#include "layout/builder.h"
#include "layout/cut_rules.h"

namespace curdle {

std::vector<std::string> SurfaceKind::keys() const {
  std::vector<std::string> keys = reading::surface_keys(surface());
  const std::vector<std::string> own = own_keys();
  keys.insert(keys.end(), own.begin(), own.end());
  if (laid_on_a_grid())
    keys.insert(keys.end(), {"min_cut", "shift", "bond", "pattern", "zones", "outline", "unit"});
  return keys;
}

void SurfaceKind::read(reading::TableReader& r, Design& design, LayoutSpec& spec,
                       bool field_given) const {
  const reading::SurfaceKeys s = surface();
  reading::read_surface(r, s, design, spec);
  read_own(r, design, spec);
  if (laid_on_a_grid()) reading::read_cut_rules(r, design, spec);
  reading::size_field(r, s.size_key, design, spec, field_given);
}

Layout SurfaceKind::build(const Design& design, const CurdField& field, const Box& view,
                          const LayoutSpec& spec) const {
  Layout layout = lay_grid(design, field, view, spec, openings(spec));
  after_laying(layout, spec);
  if (laid_on_a_grid()) check_cut_widths(layout, spec, openings(spec));
  count_values(layout, design, spec);
  layout.source.seed = field.seed;  // a kind's own draws (where a park's objects stand)
  replace_cells(layout, design, spec);
  return layout;
}

}  // namespace curdle
