#include "layout/builder.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "curdle/check.h"
#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "curdle/stop.h"
#include "layout/contour.h"
#include "layout/cut_rules.h"
#include "layout/guidance.h"
#include "layout/laying_pattern.h"
#include "layout/legend.h"
#include "layout/piece.h"
#include "layout/union.h"
#include "layout/zone.h"

namespace curdle {
namespace {

constexpr double kEps = 1e-6;

}  // namespace

double course_offset(double bond, double pitch, int64_t row) {
  if (bond <= 0) return 0;
  const double share = static_cast<double>(row) * bond;
  return (share - std::floor(share + 1e-9)) * pitch;
}

double course_offset(const LayoutSpec& spec, int64_t row) {
  return course_offset(spec.bond, spec.module_w + spec.joint, row);
}

double largest_offset(const LayoutSpec& spec, int64_t rows) {
  double most = 0;
  for (int64_t r = 0; r < std::min<int64_t>(rows, 8); ++r)
    most = std::max(most, course_offset(spec, r));
  return most;
}

double centring_shift(double extent, double module, double joint) {
  const double pitch = module + joint;
  const double whole = std::ceil((extent + joint) / pitch - 1e-9) * pitch - joint;
  const double shift = (whole - extent) / 2;
  return shift < 1e-6 ? 0 : shift;
}

std::array<int64_t, 2> elements_to_cover(const LayoutSpec& spec) {
  if (spec.kind)
    if (const auto own = spec.kind->own_cells(spec)) return *own;
  if (spec.pattern != LayingPattern::grid)
    return pattern_cells(pattern_units(spec.pattern, spec.module_w, spec.module_h, spec.joint,
                                       spec.size->at(0), spec.size->at(1)));
  const double pitch_w = spec.module_w + spec.joint, pitch_h = spec.module_h + spec.joint;
  // Element i starts at i * pitch - shift (less the course's bond offset): every element that
  // starts inside the floor is laid.
  const auto rows =
      static_cast<int64_t>(std::ceil((spec.size->at(1) + spec.shift[1]) / pitch_h - 1e-9));
  const double offset = largest_offset(spec, rows);
  return {
      static_cast<int64_t>(std::ceil((spec.size->at(0) + spec.shift[0] + offset) / pitch_w - 1e-9)),
      rows};
}

namespace {

// Where a piece crosses a sloping or curved edge (of the outline or an excluded zone), its
// exact shape: the rectangles give way to one outline (of one or more parts). Pieces wholly
// inside keep their rectangles; pieces wholly outside are left with nothing.
void cut_along_polygons(Element& e, const PolygonCuts& cuts) {
  const Rect b = laid_bounds(e);
  bool crosses = false;
  auto meet = [&](Crossing c) {
    crosses |= c == Crossing::boundary;
    return c;
  };
  if (!cuts.outline.empty() && meet(cuts.outline_crossing(b)) == Crossing::outside) {
    e.shape.clear();
    return;
  }
  for (size_t h = 0; h < cuts.holes.size(); ++h)
    if (meet(cuts.hole_crossing(h, b)) == Crossing::inside) {
      e.shape.clear();
      return;
    }
  if (!crosses) return;
  Outline piece = joined(cut_along(e.shape, cuts));
  e.shape.clear();
  if (piece.area < kEps) return;
  e.outline = std::move(piece);
  e.form = ElementForm::cut_piece;
  e.cut = true;
}

// Each element cut along the sloping and curved edges it crosses (cut_along_polygons), on as
// many threads as the run has: the exact cuts are most of a surveyed site's laying, and each
// element's cut is its own. Each task works under this thread's stop rule.
void cut_in_parallel(std::vector<Element>& elements, const PolygonCuts& cuts) {
  StopRule* rule = current_stop_rule();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, elements.size(), 64), [&](const auto& range) {
    const StopScope scope(rule);
    for (size_t i = range.begin(); i < range.end(); ++i) {
      stop_point();
      if (!elements[i].shape.empty()) cut_along_polygons(elements[i], cuts);
    }
  });
}

// Value zones give their value to the elements whose centre they hold (the first zone listed
// that holds it decides); every zone counts what it holds, and an excluded zone the pieces cut
// along it.
void apply_zones(Layout& layout, const LayoutSpec& spec, size_t values) {
  for (const Zone& z : spec.zones)
    layout.zones.push_back({z.name, z.rule, z.value, z.polygon,
                            z.contour.empty() ? polygon_area(z.polygon) : contour_area(z.contour),
                            std::vector<uint64_t>(values, 0), 0, z.contour});
  if (spec.zones.empty()) return;
  // Each zone's box, a little grown: a piece clear of it is clear of the zone, without going
  // round the zone's edges (a surveyed tree pit has hundreds, and a site thousands of pieces).
  std::vector<Rect> near;
  for (const Zone& z : spec.zones) {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const auto& [x, y] : z.polygon)
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    const double grow = std::max(1e-3, 1e-6 * std::max(x1 - x0, y1 - y0));  // over kEps
    near.push_back(z.polygon.empty()
                       ? Rect{}
                       : Rect{x0 - grow, y0 - grow, x1 - x0 + 2 * grow, y1 - y0 + 2 * grow});
  }
  for (Element& e : layout.elements) {
    stop_point();
    // The laid piece's centre: an end piece cut at the edge has its centre on the surface.
    const Rect laid = laid_bounds(e);
    const double cx = laid.x + laid.w / 2, cy = laid.y + laid.h / 2;
    std::vector<size_t> holding;
    for (size_t i = 0; i < spec.zones.size(); ++i) {
      const Zone& z = spec.zones[i];
      if (z.rects.empty() && !overlaps(near[i], e.nominal) && !overlaps(near[i], laid)) continue;
      if (z.rule == ZoneRule::exclude && e.cut &&
          (z.rects.empty() ? crossing(e.nominal, z.polygon) == Crossing::boundary
                           : std::any_of(z.rects.begin(), z.rects.end(),
                                         [&](const Rect& r) { return overlaps(r, e.nominal); })))
        ++layout.zones[i].cut;
      // An excluded zone holds a piece only where a part of it lies: a slab cut in two by a
      // drain has its parts either side and its bounds' centre in the drain, a slab cut round
      // a tree pit its bounds' centre in the pit.
      bool held = contains(z.polygon, cx, cy);
      if (held && z.rule == ZoneRule::exclude) {
        if (e.outline)
          held = std::any_of(e.outline->rings.begin(), e.outline->rings.end(), [&](const Ring& r) {
            if (signed_area(r) <= 0) return false;  // an island: its inside is not the piece's
            const auto p = point_inside(r);
            return p && contains(z.polygon, (*p)[0], (*p)[1]);
          });
        else if (e.shape.size() > 1)
          held = std::any_of(e.shape.begin(), e.shape.end(), [&](const Rect& r) {
            return contains(z.polygon, r.x + r.w / 2, r.y + r.h / 2);
          });
      }
      if (held) holding.push_back(i);
    }
    for (const size_t i : holding)
      if (spec.zones[i].rule == ZoneRule::value) {
        e.value = spec.zones[i].value;
        break;
      }
    for (const size_t i : holding) ++layout.zones[i].by_value[e.value];
  }
}

// The elements of the grid in laying order: rows from the origin corner, and along each row
// away from it; each cut at the surface's edges, its holes and `cuts`.
void lay_elements(Layout& layout, const std::vector<uint16_t>& values, const LayoutSpec& spec,
                  const PolygonCuts& cuts) {
  const std::vector<Rect> holes = layout.holes();
  const Box& view = layout.view;
  const double pitch_w = spec.module_w + spec.joint, pitch_h = spec.module_h + spec.joint;
  const bool right = from_right(spec.origin);
  const bool top = from_top(spec.origin);
  const int digits = static_cast<int>(std::to_string(std::max(layout.columns, layout.rows)).size());
  std::vector<Element>& placed = layout.elements;  // all first, then those left kept in place
  placed.reserve(values.size());
  for (int64_t row = 0; row < layout.rows; ++row) {
    for (int64_t column = 0; column < layout.columns; ++column) {
      stop_point();
      const int64_t i = right ? layout.columns - 1 - column : column;
      const int64_t j = top ? layout.rows - 1 - row : row;
      const double along = column * pitch_w - spec.shift[0] - course_offset(spec, row);
      const double up = row * pitch_h - spec.shift[1];
      Element e;
      e.row = row;
      e.column = column;
      e.cell_x = view.origin[0] + i;
      e.cell_y = view.origin[1] + j;
      e.value = values[static_cast<size_t>(j * layout.columns + i)];
      e.nominal = Rect{right ? layout.width - along - spec.module_w : along,
                       top ? layout.height - up - spec.module_h : up, spec.module_w, spec.module_h};
      e.stock_w = spec.module_w, e.stock_h = spec.module_h;
      const Rect laid = clip(e.nominal, layout.width, layout.height);
      e.shape = subtract(laid, holes);
      placed.push_back(std::move(e));
    }
  }
  if (!cuts.empty()) cut_in_parallel(placed, cuts);
  size_t kept = 0;
  for (size_t k = 0; k < placed.size(); ++k) {
    Element& e = placed[k];
    if ((e.shape.empty() && !e.outline) || e.area() < kEps) {
      ++layout.omitted;  // wholly over an opening or zone, or outside the floor or outline
      continue;
    }
    e.cut = e.cut || e.area() < e.nominal.area() - kEps;
    e.key = ElementId{spec.kind->id_letter(), digits, std::nullopt, e.row, e.column, ""};
    e.id = e.key.text();
    if (kept != k) placed[kept] = std::move(e);
    ++kept;
  }
  placed.erase(placed.begin() + static_cast<std::ptrdiff_t>(kept), placed.end());
}

// A pattern's unit as laid on the surface (`e.nominal` its extent): whole, keeping its polygon
// with no Boolean operation; cut at the surface's edges, holes and `cuts`; or false when
// nothing of it is left (wholly beyond the outline, in a zone or in an opening).
bool cut_unit_to_surface(Element& e, const Ring& ring, const Layout& layout,
                         const std::vector<Rect>& holes, const PolygonCuts& cuts) {
  const Rect& b = e.nominal;
  const Crossing outline = cuts.outline.empty() ? Crossing::inside : cuts.outline_crossing(b);
  bool gone = outline == Crossing::outside;
  bool inside = outline == Crossing::inside && b.x >= 0 && b.y >= 0 && b.right() <= layout.width &&
                b.top() <= layout.height;
  for (size_t h = 0; h < cuts.holes.size(); ++h) {
    const Crossing c = cuts.hole_crossing(h, b);
    gone = gone || c == Crossing::inside;
    inside = inside && c == Crossing::outside;
  }
  for (const Rect& h : holes) {
    gone = gone || (h.x <= b.x && h.y <= b.y && h.right() >= b.right() && h.top() >= b.top());
    inside = inside && !overlaps(h, b);
  }
  if (gone) return false;
  const double whole = polygon_area(ring);
  if (inside) {
    e.outline = Outline{{ring}, whole};
    return true;
  }
  Outline piece = joined(cut_unit(ring, Rect{0, 0, layout.width, layout.height}, holes, cuts));
  if (piece.area < kEps) return false;
  e.cut = piece.area < whole - kEps;
  e.form = e.cut ? ElementForm::cut_piece : ElementForm::piece;
  e.outline = std::move(piece);
  return true;
}

// The units of a pattern in laying order (courses from the origin corner, along each away
// from it, a basketweave square's units in turn), each cut at the surface's edges, its holes
// and `cuts`; a unit wholly inside keeps its polygon, with no Boolean operation.
void lay_pattern(Layout& layout, const std::vector<uint16_t>& values, const LayoutSpec& spec,
                 const PolygonCuts& cuts) {
  const std::vector<Rect> holes = layout.holes();
  const bool right = from_right(spec.origin), top = from_top(spec.origin);
  std::vector<PatternUnit> units = pattern_units(spec.pattern, spec.module_w, spec.module_h,
                                                 spec.joint, layout.width, layout.height);
  std::sort(units.begin(), units.end(), [](const PatternUnit& a, const PatternUnit& b) {
    return std::tie(a.row, a.column, a.part) < std::tie(b.row, b.column, b.part);
  });
  const int digits = static_cast<int>(std::to_string(std::max(layout.columns, layout.rows)).size());
  layout.elements.reserve(units.size());
  for (PatternUnit& u : units) {
    stop_point();
    // From the pattern's frame (x along the first course from the origin corner) to the
    // surface's: mirrored where laying starts on the right or at the top.
    for (auto& v : u.ring) {
      if (right) v[0] = layout.width - v[0];
      if (top) v[1] = layout.height - v[1];
    }
    if (right != top) std::reverse(u.ring.begin(), u.ring.end());
    Element e;
    e.row = u.row, e.column = u.column;
    const int64_t i = right ? layout.columns - 1 - u.column : u.column;
    const int64_t j = top ? layout.rows - 1 - u.row : u.row;
    e.cell_x = layout.view.origin[0] + i;
    e.cell_y = layout.view.origin[1] + j;
    e.value = values[static_cast<size_t>(j * layout.columns + i)];
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const auto& [x, y] : u.ring)
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    e.nominal = Rect{x0, y0, x1 - x0, y1 - y0};
    const bool rectangular = u.ring.size() == 4;
    e.stock_w = rectangular ? spec.module_w : e.nominal.w;
    e.stock_h = rectangular ? spec.module_h : e.nominal.h;
    e.turn = u.turn;
    if (right) e.turn = 180 - e.turn;
    if (top) e.turn = -e.turn;
    e.turn = std::fmod(e.turn + 360, 180);
    if (!cut_unit_to_surface(e, u.ring, layout, holes, cuts)) {
      ++layout.omitted;  // wholly over an opening or zone, or outside the floor or outline
      continue;
    }
    e.key = ElementId{spec.kind->id_letter(),
                      digits,
                      std::nullopt,
                      u.row,
                      u.column,
                      u.part ? std::to_string(u.part) : std::string()};
    e.id = e.key.text();
    layout.elements.push_back(std::move(e));
  }
  // A herringbone at 90° climbs across the cells' grid: the corners of the view take no unit.
  std::vector<bool> taken(static_cast<size_t>(layout.columns * layout.rows), false);
  for (const PatternUnit& u : units)
    taken[static_cast<size_t>(u.row * layout.columns + u.column)] = true;
  const auto unused = static_cast<size_t>(std::count(taken.begin(), taken.end(), false));
  if (unused * 10 > taken.size())
    layout.notes.push_back(fmt::format(
        "{} of the view's {} cells take no unit: the {} pattern's courses run across the cells' "
        "grid; the report counts the curd's cells, the legend and schedules the units laid",
        unused, taken.size(), pattern_name(spec.pattern)));
}

// Every element is tested against every corner of the sloping edges it may cross: a million
// elements along a 10,000-corner outline ran for minutes. Bounded before anything is laid.
void check_cutting_work(const Box& view, const PolygonCuts& cuts) {
  uint64_t corners = cuts.outline.size();
  for (const Polygon& hole : cuts.holes) corners += hole.size();
  const unsigned __int128 tests =
      static_cast<unsigned __int128>(view.size[0]) * static_cast<uint64_t>(view.size[1]) * corners;
  if (tests > kMaxCuttingWork)
    throw ResourceLimitError(
        "cutting " + std::to_string(view.size[0] * view.size[1]) + " elements along " +
        std::to_string(corners) + " corners of sloping or curved edges takes " +
        std::to_string(static_cast<uint64_t>(tests)) + " tests, above the limit of " +
        std::to_string(kMaxCuttingWork) +
        "; use larger elements, a smaller surface, or fewer corners: a larger "
        "layout.chord_tolerance gives arcs fewer (0.5 mm on a 13 m radius, a chord every 230 mm), "
        "as does a chord every 0.5 m typed into the outline (2.4 mm off the arc)");
}

}  // namespace

Layout lay_surface(const Box& view, const LayoutSpec& spec, const std::vector<Rect>& openings) {
  Layout layout;
  layout.kind = spec.kind;
  layout.combine = spec.combine;
  layout.element_type = spec.unit.empty() ? std::string(spec.kind->element_noun()) : spec.unit;
  layout.joint = spec.joint;
  layout.joint_colour = spec.joint_colour;
  layout.origin = spec.origin;
  layout.view = view;
  layout.columns = view.size[0];
  layout.rows = view.size[1];
  layout.module_w = spec.module_w;
  layout.module_h = spec.module_h;
  layout.shift = spec.shift;
  layout.bond = spec.bond;
  layout.pattern = spec.pattern;
  const double pitch_w = spec.module_w + spec.joint, pitch_h = spec.module_h + spec.joint;
  if (spec.size) {
    layout.width = (*spec.size)[0];
    layout.height = (*spec.size)[1];
  } else {
    layout.width =
        layout.columns * pitch_w - spec.joint - spec.shift[0] - largest_offset(spec, layout.rows);
    layout.height = layout.rows * pitch_h - spec.joint - spec.shift[1];
  }
  for (const Rect& o : openings) {
    const Rect c = clip(o, layout.width, layout.height);
    if (c.area() > 0) layout.openings.push_back(c);
  }
  layout.openings_given = layout.openings.size();
  for (const Zone& z : spec.zones)
    if (z.rule == ZoneRule::exclude)
      for (const Rect& r : z.rects)
        if (const Rect c = clip(r, layout.width, layout.height); c.area() > 0)
          layout.openings.push_back(c);
  layout.chord_tolerance = spec.chord_tolerance;
  layout.site = spec.site_summary;
  layout.site_frame = spec.site_frame;
  layout.notes.insert(layout.notes.end(), spec.site_notes.begin(), spec.site_notes.end());
  return layout;
}

namespace {

// The grid over `view` with the values of its cells (x fastest), `value_count` values in all.
Layout lay_values(const std::vector<uint16_t>& values, size_t value_count, const Box& view,
                  const LayoutSpec& spec, const std::vector<Rect>& openings,
                  bool with_cut_away = true) {
  Layout layout = lay_surface(view, spec, openings);
  // Edges along x and y cut pieces as rectangles; sloping or curved ones as polygons.
  PolygonCuts cuts;
  if (!spec.outline.empty()) {
    layout.outline = spec.outline;
    layout.outline_contour = spec.outline_contour;
    if (const auto inside = as_rectangles(spec.outline)) {
      for (const Rect& r : subtract(Rect{0, 0, layout.width, layout.height}, *inside))
        if (r.area() > kEps) layout.outside.push_back(r);
    } else {
      cuts.outline = spec.outline;
    }
  }
  for (const Zone& z : spec.zones)
    if (z.rule == ZoneRule::exclude && z.rects.empty()) cuts.holes.push_back(z.polygon);
  check_cutting_work(view, cuts);
  cuts.index();
  // What lies beyond the outline and in the holes (one exact overlay, a fifth of a surveyed
  // site's laying) is made beside the pieces, under this thread's stop rule. Isolated: a thread
  // waiting here for the pieces' cuts takes no other work of its caller's (a search scores
  // seeds in parallel, each with its thread's scratch, and lays each segment).
  std::vector<Outline> away;
  tbb::this_task_arena::isolate([&] {
    tbb::task_group beside;
    if (!cuts.empty() && with_cut_away)
      beside.run([&, rule = current_stop_rule()] {
        const StopScope scope(rule);
        away = cut_away(Rect{0, 0, layout.width, layout.height}, cuts);
      });
    if (spec.pattern == LayingPattern::grid)
      lay_elements(layout, values, spec, cuts);
    else
      lay_pattern(layout, values, spec, cuts);
    beside.wait();
  });
  layout.cut_away = std::move(away);
  apply_zones(layout, spec, value_count);
  return layout;
}

}  // namespace

Layout lay_grid(const Design& design, const CurdField& field, const Box& view,
                const LayoutSpec& spec, const std::vector<Rect>& openings) {
  return lay_values(values_in(field, view), size_t{1} << design.curds.size(), view, spec, openings);
}

Layout lay_blank_grid(const LayoutSpec& spec, const std::vector<Rect>& openings) {
  const auto cells = elements_to_cover(spec);
  const Box view{{0, 0, 0}, {cells[0], cells[1], 1}};
  uint32_t most = 0;
  for (const Zone& z : spec.zones) most = std::max(most, z.value);
  return lay_values(std::vector<uint16_t>(static_cast<size_t>(cells[0] * cells[1]), 0),
                    size_t{most} + 1, view, spec, openings, /*with_cut_away=*/false);
}

void count_values(Layout& layout, const Design& design, const LayoutSpec& spec) {
  advise_lattice(layout, design);
  layout.legend = make_legend(design, spec);
  for (const Element& e : layout.elements) ++layout.legend[e.value].count;
}

Layout make_layout(const Design& design, const CurdField& field, const Box& view,
                   const LayoutSpec& spec) {
  CHECK(spec.kind, "make_layout: the spec names no layout kind");
  // A fixed floor, wall, sheet or line is laid from the view's corner: the view is the segment
  // of the curd that becomes the floor, so it must have the floor's number of elements.
  if (spec.size) {
    const auto need = elements_to_cover(spec);
    if (view.size[0] != need[0] || view.size[1] != need[1])
      throw InputError("this layout's floor, wall, sheet or line takes exactly " +
                       std::to_string(need[0]) + " x " + std::to_string(need[1]) +
                       " cells, but the window is " + std::to_string(view.size[0]) + " x " +
                       std::to_string(view.size[1]) +
                       ": give a window of that size (a segment of a larger field.cells), or "
                       "leave out the layout's size and give field.cells instead");
  }
  const int dimension = spec.kind->dimension();
  if (design.lattice.dimension != dimension)
    throw InputError("this layout needs a " + std::to_string(dimension) + "-D lattice, not " +
                     std::to_string(design.lattice.dimension) + "-D");
  Layout layout = spec.kind->build(design, field, view, spec);
  layout.kind = spec.kind;
  layout.thickness = spec.kind->thickness(spec);
  layout.centred = spec.centred;
  layout.drawing = spec.drawing;
  layout.georef = spec.georef;
  layout.ordering = spec.ordering;
  layout.source.recipe = design.name;
  layout.source.description = design.description;
  layout.source.seed = field.seed;
  layout.source.lattice = design.lattice;
  layout.source.curds = design.curds;
  layout.source.field = design.field;
  return layout;
}

namespace {

// The edge before module `index` counted along an axis from the low side, in mm.
double edge(int64_t index, int64_t count, double module, double joint, double shift, double extent,
            bool from_high) {
  const double pitch = module + joint;
  if (index <= 0) return from_high ? extent - (count * pitch - joint - shift) : 0.0;
  if (index >= count) return extent;
  const int64_t from_anchor = from_high ? count - index : index;  // modules between anchor and edge
  const double at = from_anchor * pitch - joint / 2 - shift;
  return std::clamp(from_high ? extent - at : at, 0.0, extent);
}

}  // namespace

double Layout::cell_edge_x(int64_t cell_x) const {
  const bool right = from_right(origin);
  return std::max(0.0,
                  edge(cell_x - view.origin[0], columns, module_w, joint, shift[0], width, right));
}

double Layout::cell_edge_y(int64_t cell_y) const {
  const bool top = from_top(origin);
  return std::max(0.0, edge(cell_y - view.origin[1], rows, module_h, joint, shift[1], height, top));
}

}  // namespace curdle
