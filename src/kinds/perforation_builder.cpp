#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "curdle/markov.h"
#include "curdle/stop.h"
#include "kinds/perforation.h"
#include "layout/contour_clip.h"
#include "layout/surface_frame.h"
#include "layout/union.h"
#include "layout/zone.h"

namespace curdle {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Hole {
  Element element;
  std::vector<Circle> parts;  // the circles it is made of: exact gaps for the rules
  bool dropped = false;
};

// The least material between the opening and the sheet's edge: the rectangle's, or the
// outline's (negative when the opening crosses it).
double edge_gap(const Hole& h, const Layout& layout) {
  double gap = 1e300;
  for (const Circle& c : h.parts) {
    const double r = c.d / 2;
    if (layout.outline.empty()) {
      gap = std::min({gap, c.cx - r, layout.width - c.cx - r, c.cy - r, layout.height - c.cy - r});
      continue;
    }
    const double nearest = distance_to_edges(layout.outline, c.cx, c.cy);
    gap = std::min(gap, contains(layout.outline, c.cx, c.cy) ? nearest - r : -nearest - r);
  }
  return gap;
}

// Groups of circles that overlap, directly or through others.
std::vector<std::vector<Circle>> overlapping_groups(const std::vector<Circle>& circles) {
  std::vector<size_t> group(circles.size());
  std::iota(group.begin(), group.end(), 0);
  auto find = [&](size_t i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  for (size_t i = 0; i < circles.size(); ++i)
    for (size_t j = i + 1; j < circles.size(); ++j)
      if (bridge({circles[i]}, {circles[j]}) < 0) group[find(i)] = find(j);
  std::map<size_t, std::vector<Circle>> by_root;
  for (size_t i = 0; i < circles.size(); ++i) by_root[find(i)].push_back(circles[i]);
  std::vector<std::vector<Circle>> out;
  for (auto& [root, members] : by_root) out.push_back(std::move(members));
  return out;
}

// The diameter of the punch whose opening's area is nearest `area` (the larger on a tie), or
// the diameter of exactly that area when no punches are given.
double nearest_punch(const std::vector<double>& punches, double area) {
  const double exact = 2 * std::sqrt(area / kPi);
  double best = exact, miss = 1e300;
  for (const double p : punches) {
    const double m = std::fabs(kPi * p * p / 4 - area);
    if (m <= miss) best = p, miss = m;  // punches are sorted: the larger wins a tie
  }
  return best;
}

// The circle of the group that holds all the others, if one does.
const Circle* covering_circle(const std::vector<Circle>& group) {
  for (const Circle& c : group) {
    const bool holds_all = std::all_of(group.begin(), group.end(), [&](const Circle& o) {
      return std::hypot(o.cx - c.cx, o.cy - c.cy) + o.d / 2 <= c.d / 2 + 1e-9;
    });
    if (holds_all) return &c;
  }
  return nullptr;
}

std::string tool_name(const Element& e) {
  return e.circle ? fmt::format("D{:g}", std::round(e.circle->d * 1000) / 1000) : "outline";
}

}  // namespace

double bridge(const std::vector<Circle>& a, const std::vector<Circle>& b) {
  double gap = 1e300;
  for (const Circle& p : a)
    for (const Circle& q : b)
      gap = std::min(gap, std::hypot(p.cx - q.cx, p.cy - q.cy) - (p.d + q.d) / 2);
  return gap;
}

namespace {

// Each sheet's open area (checked against layout.open_area) and its openings per tool.
void summarise_sheets(Layout& layout, const LayoutSpec& spec) {
  const PerforationKeys& keys = spec.own<PerforationKeys>();
  layout.fabrication->material = keys.sheet_material;
  layout.fabrication->stock =
      keys.sheet_size.value_or(std::array<double, 2>{layout.width, layout.height});
  std::vector<std::map<std::string, uint64_t>> tools(layout.fabrication->sheets.size());
  std::vector<double> open(layout.fabrication->sheets.size(), 0.0);
  for (const Element& e : layout.elements) {
    stop_point();
    ++tools[static_cast<size_t>(e.sheet)][tool_name(e)];
    open[static_cast<size_t>(e.sheet)] += e.area();
  }
  double least = 1, most = 0;
  for (size_t i = 0; i < layout.fabrication->sheets.size(); ++i) {
    FabricationSheet& sheet = layout.fabrication->sheets[i];
    sheet.open_area = sheet.surface > 0 ? open[i] / sheet.surface : 0;
    sheet.tools.assign(tools[i].begin(), tools[i].end());
    least = std::min(least, sheet.open_area), most = std::max(most, sheet.open_area);
    const auto& range = spec.own<PerforationKeys>().open_area;
    if (range && (sheet.open_area < (*range)[0] - 1e-12 || sheet.open_area > (*range)[1] + 1e-12))
      layout.violations.push_back(
          fmt::format("{}: open area {:.2f} %, outside layout.open_area {:.2f} % to {:.2f} %",
                      sheet.id, 100 * sheet.open_area, 100 * (*range)[0], 100 * (*range)[1]));
  }
  if (layout.fabrication->sheets.size() > 1)
    layout.notes.push_back(fmt::format("{} sheets, from {:.2f} % to {:.2f} % open",
                                       layout.fabrication->sheets.size(), 100 * least, 100 * most));
}

// Each group of circles as seen from its cell's centre, and the union of that group there: every
// cell with the same curds has the same merged opening, so CGAL's union runs once per shape
// instead of once per cell (thousands of times on a perforated screen).
using UnionsByShape = std::map<std::vector<std::array<double, 3>>, Outline>;

Outline merged_outline(const std::vector<Circle>& group, double cx, double cy, double tolerance,
                       UnionsByShape& unions) {
  std::vector<std::array<double, 3>> shape;
  // To a nanometre, so that one shape is one key wherever its cell lies.
  auto nm = [](double v) { return std::round(v * 1e6) / 1e6; };
  for (const Circle& c : group) shape.push_back({nm(c.cx - cx), nm(c.cy - cy), c.d});
  auto [it, added] = unions.try_emplace(shape);
  if (added) {
    std::vector<Circle> centred;
    for (const auto& [x, y, d] : shape) centred.push_back(Circle{x, y, d});
    it->second = union_of_circles(centred, tolerance).front();
  }
  Outline placed = it->second;
  for (Ring& ring : placed.rings)
    for (auto& [x, y] : ring) x += cx, y += cy;
  placed.circles = group;
  return placed;
}

// The openings of each cell: its curds' circles, those that overlap merged (mix) or joined
// (keep), in laying order.
std::vector<Hole> make_holes(const std::vector<Element>& cells, const Design& design,
                             const LayoutSpec& spec) {
  const PerforationKeys& keys = spec.own<PerforationKeys>();
  std::vector<Hole> holes;
  UnionsByShape unions;
  for (const Element& cell : cells) {
    if (cell.value == 0) continue;
    const double cx = cell.nominal.x + cell.nominal.w / 2, cy = cell.nominal.y + cell.nominal.h / 2;
    std::vector<Circle> circles;
    for (const size_t m : members_of(design.curds, cell.value))
      circles.push_back(
          Circle{cx + keys.holes[m].offset_x, cy + keys.holes[m].offset_y, keys.holes[m].diameter});
    int index = 0;
    for (const std::vector<Circle>& group : overlapping_groups(circles)) {
      Hole h;
      h.element = cell;
      h.element.shape.clear();
      h.element.outline.reset();  // the cell's own cut along an outline is not the opening's
      h.element.cut = false;
      h.element.stock_w = h.element.stock_h = 0;  // punched or cut out: nothing is bought
      h.element.form = ElementForm::opening;
      h.element.key = cell.key.within('H', std::to_string(++index));
      h.element.id = h.element.key.text();
      if (group.size() == 1) {
        h.element.circle = group[0];
        h.parts = group;
      } else if (spec.combine == Combine::mix) {
        // One opening of the summed area at the group's centre of area (a + b = c), cut with
        // the punch whose area is nearest when the tools are given.
        double area = 0, mx = 0, my = 0;
        for (const Circle& c : group)
          area += c.area(), mx += c.area() * c.cx, my += c.area() * c.cy;
        const double d = nearest_punch(keys.punches, area);
        const Circle merged{mx / area, my / area, d};
        h.element.circle = merged;
        h.parts = {merged};
      } else if (const Circle* whole = covering_circle(group)) {
        h.element.circle = *whole;  // the others lie inside it: the union is that circle
        h.parts = {*whole};
      } else {
        h.element.outline = merged_outline(group, cx, cy, keys.chord_tolerance, unions);
        h.parts = group;
      }
      holes.push_back(std::move(h));
    }
  }

  return holes;
}

// The fabrication rules, in laying order so that reports and fixes are reproducible: smallest
// diameter, edge margin, then the bridge between neighbouring openings.
void apply_rules(std::vector<Hole>& holes, Layout& layout, const PerforationKeys& keys) {
  const bool fix = keys.fix == HoleFix::drop;
  auto drop = [&](Hole& h, const std::string& why) {
    layout.violations.push_back(h.element.id + ": " + why + (fix ? "; dropped" : ""));
    if (fix) h.dropped = true;
  };
  for (Hole& h : holes) {
    if (h.element.circle && h.element.circle->d < keys.min_diameter - 1e-9)
      drop(h, fmt::format("diameter {:.2f} mm is below the minimum {:.2f} mm", h.element.circle->d,
                          keys.min_diameter));
    else if (const double gap = edge_gap(h, layout); gap < keys.edge_margin - 1e-9)
      drop(h, fmt::format("{:.2f} mm from the sheet edge, below the margin {:.2f} mm", gap,
                          keys.edge_margin));
  }
  std::map<std::pair<int64_t, int64_t>, std::vector<size_t>> by_cell;
  for (size_t i = 0; i < holes.size(); ++i)
    by_cell[{holes[i].element.row, holes[i].element.column}].push_back(i);
  for (size_t i = 0; i < holes.size(); ++i) {
    if (holes[i].dropped) continue;
    for (int64_t dr = -1; dr <= 1 && !holes[i].dropped; ++dr)
      for (int64_t dc = -1; dc <= 1 && !holes[i].dropped; ++dc) {
        auto it = by_cell.find({holes[i].element.row + dr, holes[i].element.column + dc});
        if (it == by_cell.end()) continue;
        for (size_t j : it->second) {
          if (j <= i || holes[j].dropped) continue;
          const double gap = bridge(holes[i].parts, holes[j].parts);
          if (gap >= keys.min_bridge - 1e-9) continue;
          // The smaller opening goes (the later one on a tie), so the larger keeps its place.
          Hole& loser = holes[i].element.area() < holes[j].element.area() ? holes[i] : holes[j];
          const Hole& other = &loser == &holes[i] ? holes[j] : holes[i];
          drop(loser, fmt::format("bridge {:.2f} mm to {} is below {:.2f} mm", gap,
                                  other.element.id, keys.min_bridge));
          if (holes[i].dropped) break;
        }
      }
  }
}

// The fabrication sheets of a flat surface: rows and columns of at most the sheet size from
// the origin, the last of each cut to the surface.
void flat_sheets(Layout& layout, double sw, double sh) {
  const int nx = static_cast<int>(std::ceil(layout.width / sw - 1e-9));
  const int ny = static_cast<int>(std::ceil(layout.height / sh - 1e-9));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      layout.fabrication->sheets.push_back(
          {fmt::format("S-R{}-C{}", j + 1, i + 1),
           Rect{i * sw, j * sh, std::min(sw, layout.width - i * sw),
                std::min(sh, layout.height - j * sh)}});
}

// Where a façade's sheets are: its first in layout.fabrication->sheets, its columns' width and
// count.
struct FacadeSheets {
  double start = 0, end = 0, top = 0, width = 0;
  int columns = 0, rows = 0;
  size_t first = 0;
};

// A screen on a building: each façade cut into columns of equal width no wider than a sheet
// (a sheet never turns a corner), rows of at most a sheet's height from the base; a sheet on
// an arc is rolled to it, its blank developed at mid-thickness.
std::vector<FacadeSheets> facade_sheets(Layout& layout, const Envelope& env, double sw, double sh,
                                        double t) {
  std::vector<FacadeSheets> out;
  for (const SurfaceFrame& f : env.facades) {
    const double height = f.height > 0 ? f.height : env.height;
    const int nx = std::max(1, static_cast<int>(std::ceil(f.length / sw - 1e-9)));
    const int ny = std::max(1, static_cast<int>(std::ceil(height / sh - 1e-9)));
    const double w = f.length / nx;
    out.push_back(
        {f.start, f.start + f.length, height, w, nx, ny, layout.fabrication->sheets.size()});
    const double outer = frame_radius(f);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        FabricationSheet s{fmt::format("S-{}-R{}-C{}", f.name, j + 1, i + 1),
                           Rect{f.start + i * w, j * sh, w, std::min(sh, height - j * sh)}};
        s.facade = f.name;
        if (outer > 0) {
          s.bend_radius = std::min(outer, frame_radius_behind(f, t));
          s.developed = frame_radius_behind(f, t / 2) / outer;
        }
        layout.fabrication->sheets.push_back(std::move(s));
      }
  }
  return out;
}

// The sheet of a screen on a building that holds (x, y), or -1 (above a lower façade's top).
int sheet_holding(const std::vector<FacadeSheets>& facades, double sh, double x, double y) {
  auto f = std::upper_bound(facades.begin(), facades.end(), x,
                            [](double u, const FacadeSheets& s) { return u < s.start; });
  if (f == facades.begin()) return -1;
  --f;
  const int i = std::clamp(static_cast<int>((x - f->start) / f->width), 0, f->columns - 1);
  const int j = static_cast<int>(y / sh);
  if (x > f->end || y < 0 || y >= f->top || j >= f->rows) return -1;
  return static_cast<int>(f->first) + j * f->columns + i;
}

// Fabrication sheets of at most `size`: every opening keeps the edge margin inside its own
// sheet, so one that crosses a seam or comes within the margin of it is dropped (the stated
// rule), and reported.
void cut_into_sheets(std::vector<Hole>& holes, Layout& layout, const PerforationKeys& keys) {
  if (!keys.sheet_size && !keys.envelope) return;
  const std::array<double, 2> size =
      keys.sheet_size.value_or(std::array<double, 2>{layout.width, layout.height});
  const double sw = size[0], sh = size[1];
  std::vector<FacadeSheets> facades;
  if (keys.envelope)
    facades = facade_sheets(layout, *keys.envelope, sw, sh, keys.thickness);
  else
    flat_sheets(layout, sw, sh);
  const int nx = static_cast<int>(std::ceil(layout.width / sw - 1e-9));
  const int ny = static_cast<int>(std::ceil(layout.height / sh - 1e-9));
  for (Hole& h : holes) {
    if (h.dropped) continue;
    const Circle& first = h.parts.front();
    const int index = keys.envelope ? sheet_holding(facades, sh, first.cx, first.cy)
                                    : std::clamp(static_cast<int>(first.cy / sh), 0, ny - 1) * nx +
                                          std::clamp(static_cast<int>(first.cx / sw), 0, nx - 1);
    if (index < 0) {  // above a lower façade's top
      h.dropped = true;
      continue;
    }
    const Rect& a = layout.fabrication->sheets[static_cast<size_t>(index)].area;
    double gap = 1e300;
    for (const Circle& c : h.parts) {
      const double r = c.d / 2;
      gap =
          std::min({gap, c.cx - r - a.x, a.right() - c.cx - r, c.cy - r - a.y, a.top() - c.cy - r});
    }
    // A seam keeps the edge margin on each side, and never less than a bridge.
    const double clear = std::max(keys.edge_margin, keys.min_bridge);
    if (gap < clear - 1e-9) {
      layout.violations.push_back(fmt::format(
          "{}: {:.2f} mm from the edge of sheet {}, below {:.2f} mm; dropped "
          "(openings never cross a seam)",
          h.element.id, gap, layout.fabrication->sheets[static_cast<size_t>(index)].id, clear));
      h.dropped = true;
    } else {
      h.element.sheet = index;
    }
  }
}

// The sheets cut along an outline (a sheet wholly beyond it is not made), and the openings
// kept on them; returns the open area.
double keep_on_sheets(std::vector<Hole>& holes, Layout& layout) {
  if (layout.fabrication->sheets.empty())
    layout.fabrication->sheets.push_back({"S-R1-C1", {0, 0, layout.width, layout.height}});
  // An outline cuts the sheets to it; a sheet wholly beyond it is not cut at all.
  std::vector<int> renumbered(layout.fabrication->sheets.size(), -1);
  std::vector<FabricationSheet> kept;
  for (size_t i = 0; i < layout.fabrication->sheets.size(); ++i) {
    FabricationSheet& sheet = layout.fabrication->sheets[i];
    sheet.surface = sheet.area.area();
    if (!layout.outline.empty()) {
      PolygonCuts along;
      along.outline = layout.outline;
      const Outline cut = joined(cut_along({sheet.area}, along));
      sheet.outline = cut.rings;
      sheet.surface = cut.area;
      if (!layout.outline_contour.empty())  // for the cutter: the sheet's part of the true arcs
        sheet.outline_contour =
            clip_contour_to_box(layout.outline_contour, sheet.area, layout.chord_tolerance)
                .value_or(Contour{});
      if (sheet.surface < 1e-6) continue;
    }
    renumbered[i] = static_cast<int>(kept.size());
    kept.push_back(std::move(sheet));
  }
  layout.fabrication->sheets = std::move(kept);
  double open = 0, surface = 0;
  for (const auto& sheet : layout.fabrication->sheets) surface += sheet.surface;
  for (Hole& h : holes) {
    if (h.dropped) continue;
    // One sheet: the whole surface.
    h.element.sheet = h.element.sheet < 0 ? 0 : renumbered[static_cast<size_t>(h.element.sheet)];
    if (h.element.sheet < 0) continue;  // on a sheet wholly beyond the outline: never laid
    open += h.element.area();
    layout.elements.push_back(std::move(h.element));
  }
  return surface > 0 ? open / surface : 0;
}

}  // namespace

void perforate(Layout& layout, const Design& design, const LayoutSpec& spec) {
  const PerforationKeys& keys = spec.own<PerforationKeys>();
  std::vector<Element> cells = std::move(layout.elements);
  layout.elements.clear();
  layout.element_type = "opening";
  std::vector<Hole> holes = make_holes(cells, design, spec);
  const bool fix = keys.fix == HoleFix::drop;
  layout.drops_violations = fix;
  layout.chord_tolerance = keys.chord_tolerance;
  layout.fabrication.emplace();  // its sheets, cut below
  apply_rules(holes, layout, keys);
  cut_into_sheets(holes, layout, keys);
  layout.open_area = keep_on_sheets(holes, layout);
  const size_t broken = layout.violations.size();
  summarise_sheets(layout, spec);
  // The legend counts what is punched, by value: the openings laid (merged ones under the value
  // of their cell, dropped ones not at all), as punching.csv and quantities.csv count them; the
  // report's values count the cells. Value 0 is bare sheet, drawn but not counted.
  layout.legend[0].colour = Rgb{201, 205, 210};
  layout.legend[0].label = "sheet";
  for (LegendEntry& entry : layout.legend) entry.count = 0;
  for (const Element& e : layout.elements)
    if (e.value != 0) ++layout.legend[e.value].count;
  if (broken)
    layout.notes.push_back(fmt::format("{} openings break the fabrication rules{}", broken,
                                       fix ? " and were dropped" : " (see the report)"));
  if (layout.violations.size() > broken)
    layout.notes.push_back(
        fmt::format("{} outside layout.open_area (see the report)",
                    layout.violations.size() - broken == 1
                        ? std::string("1 sheet is")
                        : fmt::format("{} sheets are", layout.violations.size() - broken)));
  layout.notes.push_back(fmt::format("open area {:.2f} % of the sheet; sheet {} mm thick",
                                     100 * layout.open_area, keys.thickness));
}

}  // namespace curdle
