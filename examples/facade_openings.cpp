// A 9 x 6 m façade of 900 x 600 mm panels with two windows and a door: which panels are
// whole, which are cut to shape around the openings, and that the areas add up.
#include <cmath>
#include <cstdio>

#include "curdle/curdling.h"
#include "layout/builder.h"
#include "layout/joint_area.h"
#include "recipe/recipe.h"

int main() {
  const curdle::Recipe recipe = curdle::parse_recipe(R"(
    name = "façade with openings"
    [lattice]
    base = 2
    dimension = 2
    [[curds]]
    name = "light"
    probabilities = ["0.8", "0.7", "0.7", "0.8"]
    [[curds]]
    name = "dark"
    probabilities = ["0.6", "0.8", "0.7", "0.7"]
    [layout]
    kind = "facade"
    panel = [900, 600]
    joint = 12
    wall = [9000, 6000]
    openings = [[1000, 1000, 1500, 1800], [6000, 3300, 2200, 1500], [4000, 0, 1200, 2400]]
  )",
                                                     "facade_openings.cpp");
  const curdle::LayoutSpec& spec = *recipe.layout;
  const curdle::CurdField field = curdle::curdle(recipe.design, 5, recipe.design.field);
  const curdle::Layout layout =
      curdle::make_layout(recipe.design, field, recipe.design.field, spec);

  size_t whole = 0, cut = 0;
  double panels = 0, openings = 0;
  for (const auto& e : layout.elements) {
    (e.cut ? cut : whole) += 1;
    panels += e.area();
  }
  for (const auto& o : layout.openings) openings += o.area();
  const double total = panels + curdle::joint_area(layout) + openings;
  std::printf("panels: %zu whole, %zu cut to shape, %llu left out over openings\n", whole, cut,
              static_cast<unsigned long long>(layout.omitted));
  std::printf("areas: panels %.3f + joints %.3f + openings %.3f = %.3f m2 of %.3f m2\n",
              panels / 1e6, curdle::joint_area(layout) / 1e6, openings / 1e6, total / 1e6,
              9.0 * 6.0);
  return std::fabs(total - 9000.0 * 6000.0) < 1.0 ? 0 : 1;
}
