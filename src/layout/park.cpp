#include "layout/park.h"

#include <fmt/format.h>

namespace curdle {

std::vector<Rect> object_slots(const Rect& cell, size_t count, double clearance) {
  std::vector<Rect> slots;
  if (count == 0) return slots;
  const Rect inner{cell.x + clearance, cell.y + clearance, cell.w - 2 * clearance,
                   cell.h - 2 * clearance};
  const double n = static_cast<double>(count);
  for (size_t i = 0; i < count; ++i) {
    if (inner.w >= inner.h) {
      const double w = (inner.w - (n - 1) * clearance) / n;
      slots.push_back(Rect{inner.x + i * (w + clearance), inner.y, w, inner.h});
    } else {
      const double h = (inner.h - (n - 1) * clearance) / n;
      slots.push_back(Rect{inner.x, inner.y + i * (h + clearance), inner.w, h});
    }
  }
  return slots;
}

void plant(Layout& layout, const Design& design, const LayoutSpec& spec) {
  std::vector<Element> cells = std::move(layout.elements);
  layout.elements.clear();
  layout.element_type = "element";
  for (const Element& cell : cells) {
    std::vector<size_t> surfaces, objects;
    for (size_t c = 0; c < design.curds.size(); ++c)
      if (cell.value >> c & 1) (spec.park().elements[c].surface ? surfaces : objects).push_back(c);
    auto add = [&](const ParkElement& kind, std::vector<Rect> shape, std::optional<Circle> circle,
                   const std::string& suffix) {
      Element e = cell;
      e.key = cell.key.within('K', suffix);
      e.id = e.key.text();
      e.type = kind.type;
      e.colour = kind.colour;
      e.shape = std::move(shape);
      e.circle = circle;
      // Surfaces are laid to their share of the cell; objects come whole.
      if (circle)
        e.stock_w = e.stock_h = circle->d;
      else if (!e.shape.empty())
        e.stock_w = e.shape.front().w, e.stock_h = e.shape.front().h;
      e.cut = false;
      layout.elements.push_back(std::move(e));
    };
    // The ground, or the surfaces of the curds present in strips side by side.
    const Rect laid = cell.shape.empty() ? cell.nominal : cell.shape.front();
    if (surfaces.empty()) {
      add(spec.park().ground, {laid}, std::nullopt, "ground");
    } else {
      const double w = laid.w / static_cast<double>(surfaces.size());
      for (size_t i = 0; i < surfaces.size(); ++i)
        add(spec.park().elements[surfaces[i]], {Rect{laid.x + i * w, laid.y, w, laid.h}},
            std::nullopt, design.curds[surfaces[i]].name);
    }
    const std::vector<Rect> slots =
        object_slots(cell.nominal, objects.size(), spec.park().clearance);
    for (size_t i = 0; i < objects.size(); ++i) {
      const ParkElement& kind = spec.park().elements[objects[i]];
      const double cx = slots[i].x + slots[i].w / 2, cy = slots[i].y + slots[i].h / 2;
      if (kind.round)
        add(kind, {}, Circle{cx, cy, kind.w}, design.curds[objects[i]].name);
      else
        add(kind, {Rect{cx - kind.w / 2, cy - kind.h / 2, kind.w, kind.h}}, std::nullopt,
            design.curds[objects[i]].name);
    }
  }
}

}  // namespace curdle
