// The façade kind: windows and doors as rectangles in millimetres, or a mask image, cut out of
// the wall's grid; its open share reported.
#include "kinds/facade.h"

#include <cmath>

#include "layout/cut_rules.h"

namespace curdle {

std::unique_ptr<KindKeys> FacadeKind::default_keys() const {
  return std::make_unique<FacadeKeys>();
}

bool FacadeKind::take_opening(LayoutSpec& spec, const std::array<double, 4>& r) const {
  spec.own<FacadeKeys>().openings.push_back(Rect{r[0], r[1], r[2], r[3]});
  return true;
}

std::vector<Rect> FacadeKind::openings(const LayoutSpec& spec) const {
  return spec.own<FacadeKeys>().openings;
}

void FacadeKind::after_laying(Layout& layout, const LayoutSpec& spec) const {
  // The façade's own openings come first in layout.openings, as far as they lie on the wall.
  size_t on_wall = 0;
  for (const Rect& o : spec.own<FacadeKeys>().openings)
    on_wall += clip(o, layout.width, layout.height).area() > 0;
  report_open_area(layout, on_wall);
}

void FacadeKind::read_own(reading::TableReader& r, const Design&, LayoutSpec& spec) const {
  using namespace reading;
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
      spec.own<FacadeKeys>().openings.push_back(rect);
    }
  }
  spec.own<FacadeKeys>().mask = read_string(r, "mask", "the path of an image").value_or("");
}

}  // namespace curdle
