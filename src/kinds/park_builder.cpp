#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "curdle/markov.h"
#include "kinds/park.h"
#include "kinds/park_placing.h"
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

namespace {

// The objects placed so far: each one's footprint, and each tree's pit.
struct Placed {
  std::vector<Rect> footprints, pits;
  static bool any_overlap(const std::vector<Rect>& rects, const Rect& r) {
    if (r.area() <= 0) return false;
    return std::any_of(rects.begin(), rects.end(), [&r](const Rect& o) { return overlaps(o, r); });
  }
};

// The cells by where they stand on their grid, so that a pit asks only the cells round it.
class CellGrid {
 public:
  explicit CellGrid(const std::vector<Element>& cells) : cells_(cells) {
    if (cells.empty()) return;
    pitch_x_ = std::max(cells[0].nominal.w, 1.0), pitch_y_ = std::max(cells[0].nominal.h, 1.0);
    for (size_t i = 0; i < cells.size(); ++i) {
      const Rect& n = cells[i].nominal;
      // Cells of one size: a rectangle meets only those of its buckets and the ones before.
      uniform_ = uniform_ && n.w <= pitch_x_ && n.h <= pitch_y_;
      at_[{bucket(n.x, pitch_x_), bucket(n.y, pitch_y_)}].push_back(i);
    }
  }
  // How much of r the laid cells hold (the site less its edge, outline and excluded zones).
  double laid_area(const Rect& r) const {
    double area = 0;
    if (!uniform_) {
      for (const Element& c : cells_)
        if (overlaps(c.nominal, r)) area += within(c, r).area();
      return area;
    }
    for (int64_t bx = bucket(r.x, pitch_x_) - 1; bx <= bucket(r.right(), pitch_x_); ++bx)
      for (int64_t by = bucket(r.y, pitch_y_) - 1; by <= bucket(r.top(), pitch_y_); ++by)
        if (const auto it = at_.find({bx, by}); it != at_.end())
          for (const size_t i : it->second)
            if (overlaps(cells_[i].nominal, r)) area += within(cells_[i], r).area();
    return area;
  }

 private:
  static int64_t bucket(double v, double pitch) {
    return static_cast<int64_t>(std::floor(v / pitch));
  }
  const std::vector<Element>& cells_;
  double pitch_x_ = 1, pitch_y_ = 1;
  bool uniform_ = true;
  std::map<std::pair<int64_t, int64_t>, std::vector<size_t>> at_;
};

// Where an object stands: its centre and footprint.
struct Placing {
  double cx = 0, cy = 0;
  Rect footprint;
};

constexpr uint32_t kPlacingAttempts = 8;

// Where an object of `size` stands in its slot: drawn from the cell's own stream (a bench at
// its slot's edge on the side it faces), drawn again while it would not stand clear of the
// cell's laid edges by the clearance, or its pit would not lie in laid ground clear of the
// other objects and pits; the slot's centre last. Nothing when none of those will do.
std::optional<Placing> place(const Element& cell, const Rect& slot, const ParkElement& kind,
                             const std::array<double, 2>& size, int bearing, uint64_t seed,
                             uint32_t member, const CellGrid& cells, double clearance,
                             Placed& placed) {
  const double fw = size[0], fh = size[1];
  const double free_x = std::max(0.0, slot.w - fw), free_y = std::max(0.0, slot.h - fh);
  for (uint32_t attempt = 0; attempt <= kPlacingAttempts; ++attempt) {
    double x = slot.x + free_x / 2, y = slot.y + free_y / 2;
    if (attempt < kPlacingAttempts) {
      const std::array<double, 4> u =
          placing_draws(seed, cell.cell_x, cell.cell_y, member, attempt);
      x = slot.x + u[0] * free_x, y = slot.y + u[1] * free_y;
      if (!kind.round) {  // a bench backs onto its slot's far side, facing out
        if (bearing == 0) y = slot.y + free_y;
        if (bearing == 180) y = slot.y;
        if (bearing == 90) x = slot.x + free_x;
        if (bearing == 270) x = slot.x;
      }
    }
    const Rect footprint{x, y, fw, fh};
    const double cx = x + fw / 2, cy = y + fh / 2;
    const Rect room{x - clearance, y - clearance, fw + 2 * clearance, fh + 2 * clearance};
    const PlantingSpec& order = kind.order;
    const Rect pit = order.pit_given() ? centred_on(cx, cy, order.pit[0], order.pit[1]) : Rect{};
    const bool in_slot = footprint.x >= slot.x - kEps && footprint.y >= slot.y - kEps &&
                         footprint.right() <= slot.right() + kEps &&
                         footprint.top() <= slot.top() + kEps;
    if (!in_slot || within(cell, room).area() < room.area() - kEps ||
        Placed::any_overlap(placed.pits, footprint))
      continue;
    if (pit.area() > 0 &&
        (cells.laid_area(pit) < pit.area() - kEps || Placed::any_overlap(placed.footprints, pit) ||
         Placed::any_overlap(placed.pits, pit)))
      continue;
    placed.footprints.push_back(footprint);
    if (pit.area() > 0) placed.pits.push_back(pit);
    return Placing{cx, cy, footprint};
  }
  return std::nullopt;
}

// Where a bench looks, and so which way its long side runs: towards the nearest piece of the
// surface it faces in another cell, or the zone it faces; south when there is none.
int bench_bearing(const std::array<double, 2>& at, const ParkElement& kind, const LayoutSpec& spec,
                  const std::vector<std::vector<Element>>& surfaces, size_t own) {
  const std::string& faces = kind.faces.empty() ? spec.own<ParkKeys>().ground.type : kind.faces;
  for (const Zone& z : spec.zones)
    if (z.name == faces) return bearing_towards(at, z.polygon).value_or(180);
  std::vector<Rect> targets;
  for (size_t i = 0; i < surfaces.size(); ++i)
    for (const Element& piece : surfaces[i])
      if (i != own && piece.type == faces) targets.push_back(laid_bounds(piece));
  return bearing_towards(at, targets).value_or(180);
}

}  // namespace

void plant(Layout& layout, const Design& design, const LayoutSpec& spec) {
  const std::vector<Element> cells = std::move(layout.elements);
  layout.elements.clear();
  layout.element_type = "element";
  const ParkKeys& park = spec.own<ParkKeys>();
  const std::vector<CurdMember> members = curd_members(design.curds);
  ParkPlanting& planting = layout.planting.emplace();
  for (size_t m = 0; m < members.size(); ++m)
    if (const ParkElement& kind = park.elements[m]; !kind.surface) {
      planting.orders.push_back(kind.order);
      planting.orders.back().member = members[m].name;  // as the elements' IDs end
    }
  // A cell's element: its key, form and look from the cell and the kind.
  auto element = [&](const Element& cell, const ParkElement& kind, Region region,
                     std::optional<Circle> circle, const std::string& suffix, const Rect& stock) {
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
    return e;
  };
  // First every cell's ground, or the surfaces of the curds present in strips side by side, as
  // far as the cell is laid (an area's edge or an outline may cut it): benches face them.
  std::vector<std::vector<Element>> surfaces(cells.size());
  for (size_t c = 0; c < cells.size(); ++c) {
    const Element& cell = cells[c];
    std::vector<size_t> laid;
    for (const size_t m : members_of(design.curds, cell.value))
      if (park.elements[m].surface) laid.push_back(m);
    const Rect bounds = laid_bounds(cell);
    if (laid.empty()) {
      surfaces[c].push_back(
          element(cell, park.ground, within(cell, bounds), std::nullopt, "ground", bounds));
      continue;
    }
    const double w = bounds.w / static_cast<double>(laid.size());
    for (size_t i = 0; i < laid.size(); ++i) {
      const Rect strip{bounds.x + i * w, bounds.y, w, bounds.h};
      if (Region part = within(cell, strip); part.area() > kEps)
        surfaces[c].push_back(element(cell, park.elements[laid[i]], std::move(part), std::nullopt,
                                      members[laid[i]].name, strip));
    }
  }
  // Then the objects, each whole on the cell as laid or not at all.
  const CellGrid grid(cells);
  Placed placed;
  size_t left_out = 0;
  for (size_t c = 0; c < cells.size(); ++c) {
    const Element& cell = cells[c];
    for (Element& e : surfaces[c]) layout.elements.push_back(std::move(e));
    std::vector<size_t> objects;
    for (const size_t m : members_of(design.curds, cell.value))
      if (!park.elements[m].surface) objects.push_back(m);
    const std::vector<Rect> slots = object_slots(cell.nominal, objects.size(), park.clearance);
    for (size_t i = 0; i < objects.size(); ++i) {
      const ParkElement& kind = park.elements[objects[i]];
      const Rect& slot = slots[i];
      // A bench turns to face its path; it stands at the edge of its slot on that side.
      const std::array<double, 2> middle{slot.x + slot.w / 2, slot.y + slot.h / 2};
      int bearing = kind.round ? 0 : bench_bearing(middle, kind, spec, surfaces, c);
      const bool across = bearing == 90 || bearing == 270;  // its long side runs along y
      double fw = kind.round ? kind.w : across ? kind.h : kind.w;
      double fh = kind.round ? kind.w : across ? kind.w : kind.h;
      if (fw > slot.w + kEps || fh > slot.h + kEps) {  // turned, it would not fit its slot
        std::swap(fw, fh);
        bearing = across ? (middle[1] < cell.nominal.y + cell.nominal.h / 2 ? 0 : 180)
                         : (middle[0] < cell.nominal.x + cell.nominal.w / 2 ? 90 : 270);
      }
      const std::optional<Placing> at =
          place(cell, slot, kind, {fw, fh}, bearing, layout.source.seed,
                static_cast<uint32_t>(objects[i]), grid, park.clearance, placed);
      if (!at) {
        ++left_out;
        continue;
      }
      Element e = kind.round ? element(cell, kind, {}, Circle{at->cx, at->cy, kind.w},
                                       members[objects[i]].name, at->footprint)
                             : element(cell, kind, Region{{at->footprint}, std::nullopt},
                                       std::nullopt, members[objects[i]].name, at->footprint);
      e.turn = kind.round ? 0 : bearing;
      layout.elements.push_back(std::move(e));
    }
  }
  if (left_out > 0)
    layout.notes.push_back(fmt::format(
        "{} object{} left out where {} would not stand whole with the clearance of {:g} mm "
        "all round (to the cell's edges, the area's edge or outline, and the other objects), "
        "or its tree pit would not lie in laid ground clear of other objects and pits",
        left_out, left_out == 1 ? " is" : "s are", left_out == 1 ? "it" : "they", park.clearance));
}

}  // namespace curdle
