#include "layout/piece.h"

#include <algorithm>

#include "curdle/stop.h"
#include "layout/union.h"

namespace curdle {

Rect laid_bounds(const Element& e) {
  if (e.circle)
    return Rect{e.circle->cx - e.circle->d / 2, e.circle->cy - e.circle->d / 2, e.circle->d,
                e.circle->d};
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  auto add = [&](double x, double y) {
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  };
  if (e.outline) {
    for (const Ring& ring : e.outline->rings)
      for (const auto& v : ring) add(v[0], v[1]);
  } else {
    for (const Rect& r : e.shape) add(r.x, r.y), add(r.right(), r.top());
  }
  if (x0 > x1) return e.nominal;
  return Rect{x0, y0, x1 - x0, y1 - y0};
}

Rect label_bounds(const Element& e) {
  const bool round_the_seam = !e.circle && !e.outline && e.shape.size() > 1 &&
                              std::any_of(e.shape.begin(), e.shape.end(), [&](const Rect& r) {
                                return carried_round_the_seam(e, r);
                              });
  if (!round_the_seam) return laid_bounds(e);
  return *std::max_element(e.shape.begin(), e.shape.end(),
                           [](const Rect& a, const Rect& b) { return a.area() < b.area(); });
}

bool is_rectangle(const Element& e) {
  if (e.circle || e.outline) return false;
  if (e.shape.size() <= 1) return true;
  const Rect b = laid_bounds(e);
  double area = 0;
  for (const Rect& r : e.shape) area += r.area();
  return area >= b.area() - 1e-6;  // disjoint pieces that fill their box
}

std::vector<Outline> piece_outlines(const Element& e) {
  if (e.outline) return outline_parts(*e.outline);  // a piece cut in two is two parts
  if (e.circle || is_rectangle(e)) return {};
  return union_of_rects(e.shape);
}

const std::string& piece_material(const Layout& layout, const Element& e) {
  if (e.type.empty()) return layout.legend[e.value].label;
  // A tree is ordered by its species: two curds' trees of one type but two species are two
  // lines of quantities.csv and the keys.
  if (const PlantingSpec& p = planting_of(layout, e); !p.species.empty()) return p.species;
  return e.type;
}

const Rgb& piece_colour(const Layout& layout, const Element& e) {
  return e.type.empty() ? layout.legend[e.value].colour : e.colour;
}

std::vector<ColouredRect> keep_stripes(const Layout& layout, const Element& e) {
  const LegendEntry& entry = layout.legend[e.value];
  std::vector<ColouredRect> out;
  if (layout.combine != Combine::keep || entry.parts.empty() || !e.type.empty()) {
    for (const Rect& r : e.shape) out.push_back({r, piece_colour(layout, e)});
    return out;
  }
  const bool right = from_right(layout.origin);
  const double part = e.nominal.w / static_cast<double>(entry.parts.size());
  for (size_t i = 0; i < entry.parts.size(); ++i) {
    const double x = right ? e.nominal.right() - (i + 1) * part : e.nominal.x + i * part;
    for (const Rect& r : e.shape) {
      const double x0 = std::max(r.x, x), x1 = std::min(r.right(), x + part);
      if (x1 > x0 + 1e-9) out.push_back({Rect{x0, r.y, x1 - x0, r.h}, entry.parts[i]});
    }
  }
  return out;
}

LayingExtents laying_extents(const Layout& layout) {
  LayingExtents x;
  for (const Element& e : layout.elements) {
    stop_point();
    auto& r = x.rows.try_emplace(e.row, 1e300, -1e300).first->second;
    r.first = std::min(r.first, e.nominal.y), r.second = std::max(r.second, e.nominal.top());
    auto& c = x.columns.try_emplace(e.column, 1e300, -1e300).first->second;
    c.first = std::min(c.first, e.nominal.x), c.second = std::max(c.second, e.nominal.right());
  }
  return x;
}

const PlantingSpec& planting_of(const Layout& layout, const Element& e) {
  static const PlantingSpec none;
  if (!e.stands || !layout.planting) return none;
  for (const PlantingSpec& p : layout.planting->orders)
    if (p.member == e.key.part) return p;
  return none;
}

std::optional<Rect> tree_pit(const Layout& layout, const Element& e) {
  const PlantingSpec& p = planting_of(layout, e);
  if (!p.pit_given()) return std::nullopt;
  const Rect b = laid_bounds(e);
  return centred_on(b.x + b.w / 2, b.y + b.h / 2, p.pit[0], p.pit[1]);
}

std::optional<std::array<std::array<double, 2>, 2>> back_edge(const Element& e) {
  if (!e.stands || e.circle || e.shape.size() != 1) return std::nullopt;
  const Rect& b = e.shape[0];
  switch (static_cast<int>(e.turn)) {
    case 0:
      return std::array<std::array<double, 2>, 2>{{{b.x, b.y}, {b.right(), b.y}}};
    case 180:
      return std::array<std::array<double, 2>, 2>{{{b.x, b.top()}, {b.right(), b.top()}}};
    case 90:
      return std::array<std::array<double, 2>, 2>{{{b.x, b.y}, {b.x, b.top()}}};
    case 270:
      return std::array<std::array<double, 2>, 2>{{{b.right(), b.y}, {b.right(), b.top()}}};
    default:
      return std::nullopt;
  }
}

uint64_t cut_elements(const Layout& layout) {
  uint64_t cut = 0;
  for (const Element& e : layout.elements) cut += e.cut;
  return cut;
}

}  // namespace curdle
