// [layout] of kind "facade": windows and doors as rectangles in millimetres, or a mask image.
#include <cmath>

#include "recipe/layout_reader.h"

namespace curdle::reading {

void read_facade(TableReader& r, LayoutSpec& spec) {
  if (const toml::node* n = r.get("openings")) {
    const toml::array* a = n->as_array();
    if (!a) r.fail("openings", "must be an array of [x, y, width, height] in millimetres");
    for (size_t i = 0; i < a->size(); ++i) {
      const toml::array* o = a->get(i)->as_array();
      const std::string path = "layout.openings." + std::to_string(i);
      std::array<double, 4> v{};
      bool ok = o && o->size() == 4;
      for (size_t k = 0; ok && k < 4; ++k) {
        const auto x = finite_number(o->get(k));
        ok = x && std::isfinite(*x) && (k < 2 ? *x >= 0 : *x > 0);
        if (ok) v[k] = *x;
      }
      if (!ok)
        r.fail_node(*a->get(i), path,
                    "must be [x, y, width, height] in millimetres from the wall's bottom-left "
                    "corner, sizes above 0");
      const Rect rect{v[0], v[1], v[2], v[3]};
      if (rect.right() > (*spec.size)[0] + 1e-6 || rect.top() > (*spec.size)[1] + 1e-6)
        r.fail_node(*a->get(i), path,
                    "lies outside the wall of " +
                        std::to_string(static_cast<int>((*spec.size)[0])) + " x " +
                        std::to_string(static_cast<int>((*spec.size)[1])) + " mm");
      spec.facade().openings.push_back(rect);
    }
  }
  spec.facade().mask = read_string(r, "mask", "the path of an image").value_or("");
}

}  // namespace curdle::reading
