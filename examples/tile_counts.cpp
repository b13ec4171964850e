// A 20 x 20 m floor of 300 mm tiles (67 x 67) paved in two colours at 1 : 8, in quota mode so
// that the dark tiles hit the target count exactly: the library without the command line.
#include <cstdio>

#include "curdle/curdling.h"
#include "curdle/overlay.h"
#include "recipe/recipe.h"

int main() {
  const char* recipe_text = R"(
    name = "floor at 1:8"
    [lattice]
    base = 4
    dimension = 2
    mode = "quota"
    [field]
    cells = [67, 67]
    [[curds]]
    name = "dark"
    probabilities = ["2/3", "1/2", "1/3"]
  )";
  const curdle::Recipe recipe = curdle::parse_recipe(recipe_text, "tile_counts.cpp");
  const curdle::Design& design = recipe.design;
  const curdle::CurdField field = curdle::curdle(design, 2014, design.field);
  const auto counts = curdle::value_counts(field);
  std::printf("dark tiles: %llu of %llu (target %llu)\n",
              static_cast<unsigned long long>(counts[1]),
              static_cast<unsigned long long>(design.field.cells()),
              static_cast<unsigned long long>((design.field.cells() + 4) / 9));
  return 0;
}
