// Tests of cell_placement.h.
#include "layout/cell_placement.h"

#include <gtest/gtest.h>

#include "density_support.h"

namespace curdle {
TEST(Density, PlacementIsWhereTheLayoutLaysEachCell) {
  const Design d = test::design(4, 2, {{"1/2", "1/2", "1/2", "1/2"}});
  for (const char* corner : {"bottom-left", "bottom-right", "top-left", "top-right", "centre"})
    for (const char* bond : {"stack", "half", "third"}) {
      std::string text = std::string(R"(name = "p"
[lattice]
base = 4
dimension = 2
[[curds]]
probabilities = ["1/2", "1/2", "1/2", "1/2"]
[field]
cells = [256, 256]
[layout]
kind = "paving"
tile = [600, 300]
joint = 5
floor = [12000, 5500]
bond = ")") + bond + "\"\norigin = \"" +
                         corner + "\"\n";
      if (std::string(corner) != "centre") text += "shift = [100, 50]\n";
      Recipe r;
      try {  // laid from a window away from the field's origin
        const auto need = elements_to_cover(*parse_recipe(text, "p.toml").layout);
        r = parse_recipe(text, "p.toml",
                         {"field.window=[13, 7, " + std::to_string(need[0]) + ", " +
                          std::to_string(need[1]) + "]"});
      } catch (const InputError& e) {
        FAIL() << corner << " " << bond << ": " << e.what();
      }
      const CellPlacement p = cell_placement(*r.layout, *r.window);
      const Layout layout =
          make_layout(r.design, curdle(r.design, 1, *r.window), *r.window, *r.layout);
      ASSERT_GT(layout.elements.size(), 100u);
      for (const Element& e : layout.elements) {
        const auto c = p.centre({e.cell_x, e.cell_y, 0}, 2);
        ASSERT_NEAR(c[0], e.nominal.x + e.nominal.w / 2, 1e-6)
            << corner << " " << bond << " " << e.id;
        ASSERT_NEAR(c[1], e.nominal.y + e.nominal.h / 2, 1e-6)
            << corner << " " << bond << " " << e.id;
      }
    }
}

}  // namespace curdle
