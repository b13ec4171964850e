// A recipe read in phases: the TOML document, the overrides applied to it, the design
// (design_reader), then the layout (layout_reader), then the segment the layout is laid from.
#include "recipe/recipe.h"

#include "layout/builder.h"
#include "recipe/density_reader.h"
#include "recipe/design_reader.h"
#include "recipe/layout_reader.h"
#include "recipe/overrides.h"
#include "recipe/toml_reader.h"

namespace curdle {

using namespace reading;

Recipe parse_recipe(std::string_view text, const std::string& source,
                    const std::vector<std::string>& overrides, const RecipeFiles* files) {
  toml::table doc = parse_toml(text, source);
  Source where{source, {}, files};
  for (const auto& o : overrides) {
    apply_override(doc, o);
    where.overridden.push_back(o.substr(0, o.find('=')));
  }

  TableReader top(doc, "", where,
                  {"name", "description", "seed", "lattice", "field", "curds", "layout"});
  Recipe recipe;
  recipe.design.name = read_name(top, "name").value_or("untitled");
  recipe.design.description = read_string(top, "description").value_or("");
  recipe.seed = read_seed(top);
  Lattice lattice = read_lattice(top);
  recipe.design.curds = read_curds(top, lattice);
  check_size(top, lattice);
  check_exact(top, lattice, recipe.design.curds);
  recipe.design.lattice = lattice;
  recipe.design.field = read_field(top, lattice, recipe.window);
  const toml::table* field_table = doc.get("field") ? doc.get("field")->as_table() : nullptr;
  recipe.layout = read_layout(top, recipe.design, field_table && field_table->get("cells"));
  if (recipe.layout && recipe.layout->size && !recipe.window) {
    // The floor is laid from a segment of its own size; by default the one at the origin.
    const auto need = elements_to_cover(*recipe.layout);
    if (need[0] != recipe.design.field.size[0] || need[1] != recipe.design.field.size[1]) {
      Box segment;
      segment.size = {need[0], need[1], 1};
      recipe.window = segment;
    }
  }
  if (recipe.window && !recipe.design.field.contains(*recipe.window)) {
    std::string size;
    for (int d = 0; d < lattice.dimension; ++d)
      size += (d ? " x " : "") + std::to_string(recipe.design.field.size[d]);
    top.fail_node(*field_table->get("window"), "field.window",
                  "must lie inside the field of " + size + " cells (origin + size <= field)");
  }
  if (recipe.window && recipe.layout && recipe.layout->size) {
    const auto need = elements_to_cover(*recipe.layout);
    if (recipe.window->size[0] != need[0] || recipe.window->size[1] != need[1])
      top.fail_node(*field_table->get("window"), "field.window",
                    "must be " + std::to_string(need[0]) + " x " + std::to_string(need[1]) +
                        " cells, the elements of the layout's floor, wall, sheet or line");
  }
  for (CurdSpec& curd : recipe.design.curds)
    if (curd.density)
      place_density(*curd.density, recipe.layout, recipe.window.value_or(recipe.design.field),
                    recipe.design.field);
  return recipe;
}

}  // namespace curdle
