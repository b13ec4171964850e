#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "curdle/markov.h"
#include "kinds/park.h"
#include "layout/piece.h"
#include "layout/union.h"

namespace curdle {
namespace {

constexpr double kEps = 1e-6;

// A cell as laid: whole, cut to rectangles at the area's edge or an outline along x and y, or
// cut along a sloping or curved edge (an outline).
struct Region {
  std::vector<Rect> rects;
  std::optional<Outline> outline;
  double area() const {
    if (outline) return outline->area;
    double a = 0;
    for (const Rect& r : rects) a += r.area();
    return a;
  }
};

Rect overlap(const Rect& a, const Rect& b) {
  const double x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
  const double x1 = std::min(a.right(), b.right()), y1 = std::min(a.top(), b.top());
  return x1 > x0 && y1 > y0 ? Rect{x0, y0, x1 - x0, y1 - y0} : Rect{};
}

// The part of r the cell has.
Region within(const Element& cell, const Rect& r) {
  Region out;
  if (cell.outline) {
    Outline part = joined(clip_outline(r, *cell.outline));
    if (part.area > kEps) out.outline = std::move(part);
    return out;
  }
  for (const Rect& c : cell.shape)
    if (const Rect o = overlap(c, r); o.area() > kEps) out.rects.push_back(o);
  return out;
}

}  // namespace

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
  const std::vector<CurdMember> members = curd_members(design.curds);
  layout.planting.clear();
  for (size_t m = 0; m < members.size(); ++m)
    if (const ParkElement& kind = spec.own<ParkKeys>().elements[m]; !kind.surface) {
      layout.planting.push_back(kind.order);
      layout.planting.back().member = members[m].name;  // as the elements' IDs end
    }
  size_t left_out = 0;
  for (const Element& cell : cells) {
    std::vector<size_t> surfaces, objects;
    for (const size_t m : members_of(design.curds, cell.value))
      (spec.own<ParkKeys>().elements[m].surface ? surfaces : objects).push_back(m);
    auto add = [&](const ParkElement& kind, Region region, std::optional<Circle> circle,
                   const std::string& suffix, const Rect& stock) {
      Element e = cell;
      e.form = ElementForm::object;
      e.key = cell.key.within('K', suffix);
      e.id = e.key.text();
      e.type = kind.type;
      e.colour = kind.colour;
      e.shape = std::move(region.rects);
      e.outline = std::move(region.outline);
      e.circle = circle;
      e.stands = !kind.surface;
      // Surfaces are laid to their share of the cell; objects come whole.
      e.stock_w = stock.w, e.stock_h = stock.h;
      e.cut = e.outline.has_value();  // cut along a sloping or curved edge
      layout.elements.push_back(std::move(e));
    };
    // The ground, or the surfaces of the curds present in strips side by side, as far as the
    // cell is laid (an area's edge or an outline may cut it).
    const Rect laid = laid_bounds(cell);
    if (surfaces.empty()) {
      add(spec.own<ParkKeys>().ground, within(cell, laid), std::nullopt, "ground", laid);
    } else {
      const double w = laid.w / static_cast<double>(surfaces.size());
      for (size_t i = 0; i < surfaces.size(); ++i) {
        const Rect strip{laid.x + i * w, laid.y, w, laid.h};
        Region part = within(cell, strip);
        if (part.area() > kEps)
          add(spec.own<ParkKeys>().elements[surfaces[i]], std::move(part), std::nullopt,
              members[surfaces[i]].name, strip);
      }
    }
    // Objects stand whole on the cell as laid, or not at all.
    const std::vector<Rect> slots =
        object_slots(cell.nominal, objects.size(), spec.own<ParkKeys>().clearance);
    for (size_t i = 0; i < objects.size(); ++i) {
      const ParkElement& kind = spec.own<ParkKeys>().elements[objects[i]];
      const double cx = slots[i].x + slots[i].w / 2, cy = slots[i].y + slots[i].h / 2;
      const Rect footprint = kind.round ? Rect{cx - kind.w / 2, cy - kind.w / 2, kind.w, kind.w}
                                        : Rect{cx - kind.w / 2, cy - kind.h / 2, kind.w, kind.h};
      // The clearance holds all round: to the cell's laid edges (the area's edge, an outline,
      // the neighbouring cells) and to the other objects, whose slots it separates.
      const double c = spec.own<ParkKeys>().clearance;
      const Rect room{footprint.x - c, footprint.y - c, footprint.w + 2 * c, footprint.h + 2 * c};
      const bool in_slot = footprint.x >= slots[i].x - kEps && footprint.y >= slots[i].y - kEps &&
                           footprint.right() <= slots[i].right() + kEps &&
                           footprint.top() <= slots[i].top() + kEps;
      // A tree pit is dug within the cell as laid (never beyond the site's edge).
      const PlantingSpec& order = kind.order;
      const Rect pit = order.pit_given() ? centred_on(cx, cy, order.pit[0], order.pit[1]) : Rect{};
      if (!in_slot || within(cell, room).area() < room.area() - kEps ||
          within(cell, pit).area() < pit.area() - kEps) {
        ++left_out;
        continue;
      }
      if (kind.round)
        add(kind, {}, Circle{cx, cy, kind.w}, members[objects[i]].name, footprint);
      else
        add(kind, Region{{footprint}, std::nullopt}, std::nullopt, members[objects[i]].name,
            footprint);
    }
  }
  if (left_out > 0)
    layout.notes.push_back(fmt::format(
        "{} object{} left out where {} would not stand whole with the clearance of {:g} mm "
        "all round (to the cell's edges, the area's edge or outline, and the other objects), "
        "or its tree pit would not lie within the cell",
        left_out, left_out == 1 ? " is" : "s are", left_out == 1 ? "it" : "they",
        spec.own<ParkKeys>().clearance));
}

}  // namespace curdle
