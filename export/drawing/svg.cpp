#include "export/drawing/svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "curdle/palette.h"
#include "curdle/stop.h"
#include "curdle/text.h"
#include "layout/contour.h"
#include "layout/ground_colour.h"
#include "layout/legend.h"
#include "layout/piece.h"
#include "layout/title_block.h"
#include "layout/union.h"

namespace curdle {
namespace {

// All text in the drawing goes through the one XML escaper (curdle/text.h).
std::string escape(const std::string& s) { return xml_escape(s); }

std::string mm(double v) { return drawing_mm(v); }

// SVG's y runs down; the layout's runs up from the bottom of the drawing area.
struct Sheet {
  double margin, height;
  double x(double v) const { return margin + v; }
  double y(double v, double h = 0) const { return margin + height - v - h; }
};

// A rectangle of merged elements, from the first to the last of the run (see svg.h).
void write_merged(std::ostream& out, const Sheet& s, const Layout& layout,
                  const std::vector<const Element*>& at, const GridRect& g) {
  const Element& a = *at[static_cast<size_t>(g.row0 * layout.columns + g.column0)];
  const Element& b = *at[static_cast<size_t>(g.row1 * layout.columns + g.column1)];
  const double x0 = std::min(a.nominal.x, b.nominal.x),
               x1 = std::max(a.nominal.right(), b.nominal.right());
  const double y0 = std::min(a.nominal.y, b.nominal.y),
               y1 = std::max(a.nominal.top(), b.nominal.top());
  const uint64_t count = static_cast<uint64_t>((g.row1 - g.row0 + 1) * (g.column1 - g.column0 + 1));
  out << fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" data-elements=\"{}{}\" "
      "data-count=\"{}\"/>\n",
      mm(s.x(x0)), mm(s.y(y0, y1 - y0)), mm(x1 - x0), mm(y1 - y0), a.id,
      count > 1 ? ":" + b.id : std::string(), count);
}

// A closed polygon (an outline, a zone) as path data.
std::string polygon_path(const Sheet& s, const Polygon& polygon) {
  std::string d;
  for (size_t k = 0; k < polygon.size(); ++k)
    d += fmt::format("{}{} {}", k ? "L" : "M", mm(s.x(polygon[k][0])), mm(s.y(polygon[k][1])));
  return d + "z";
}

// A contour's path with its arcs as SVG arc commands. The sheet's y runs down, so a
// counter-clockwise arc (positive sweep) is drawn with sweep-flag 0.
std::string contour_path(const Sheet& s, const Contour& c) {
  std::string d;
  for (size_t k = 0; k < c.size(); ++k) {
    const ContourVertex& v = c[k];
    if (k == 0) d += fmt::format("M{} {}", mm(s.x(v.x)), mm(s.y(v.y)));
    const ContourVertex& next = c[(k + 1) % c.size()];
    if (v.bulge == 0) {
      if (k + 1 < c.size()) d += fmt::format("L{} {}", mm(s.x(next.x)), mm(s.y(next.y)));
      continue;
    }
    const Arc a = arc_between(v, next);
    d += fmt::format("A{} {} 0 {} {} {} {}", mm(a.radius), mm(a.radius),
                     std::fabs(a.sweep) > 3.14159265358979323846 ? 1 : 0, a.sweep > 0 ? 0 : 1,
                     mm(s.x(next.x)), mm(s.y(next.y)));
  }
  return d + "z";
}

// The outline or zone as drawn: with its arcs where it has any.
std::string shape_path(const Sheet& s, const Polygon& polygon, const Contour& contour) {
  return contour.empty() ? polygon_path(s, polygon) : contour_path(s, contour);
}

std::string rect_path(const Sheet& s, const Rect& r) {
  return fmt::format("M{} {}h{}v{}h{}z", mm(s.x(r.x)), mm(s.y(r.y, r.h)), mm(r.w), mm(r.h),
                     mm(-r.w));
}

// A value's group of elements: its ID, value, label and count, filled with `fill`.
std::string value_group(const LegendEntry& entry, const std::string& fill) {
  return fmt::format(
      "<g id=\"value-{}\" class=\"value\" data-value=\"{}\" data-label=\"{}\" data-count=\"{}\" "
      "fill=\"{}\">\n",
      entry.value, entry.value, escape(entry.label), entry.count, fill);
}

// The layout's elements grouped by value, in laying order within each.
std::vector<std::vector<const Element*>> elements_by_value(const Layout& layout) {
  std::vector<std::vector<const Element*>> by_value(layout.legend.size());
  for (const Element& e : layout.elements) by_value[e.value].push_back(&e);
  return by_value;
}

void draw_openings(std::ostream& out, const Layout& layout, const Sheet& s) {
  const auto by_value = elements_by_value(layout);
  for (const LegendEntry& entry : layout.legend) {
    out << value_group(entry, hex_colour(entry.colour));
    for (const Element* e : by_value[entry.value]) {
      if (e->circle) {
        out << fmt::format(
            "<circle id=\"{}\" class=\"opening\" cx=\"{}\" cy=\"{}\" r=\"{}\" "
            "data-diameter=\"{}\"/>\n",
            e->id, mm(s.x(e->circle->cx)), mm(s.y(e->circle->cy)), mm(e->circle->d / 2),
            mm(e->circle->d));
      } else if (!e->shape.empty()) {
        std::string d;
        for (const Rect& r : e->shape) d += rect_path(s, r);
        out << fmt::format("<path id=\"{}\" d=\"{}\" data-count=\"1\"/>\n", e->id, d);
      } else if (e->outline) {
        std::string d;
        for (const Ring& ring : e->outline->rings) d += polygon_path(s, ring);
        out << fmt::format(
            "<path id=\"{}\" class=\"opening merged\" fill-rule=\"evenodd\" d=\"{}\"/>\n", e->id,
            d);
      }
    }
    out << "</g>\n";
  }
}

// Blocks: the plan and the elevation, one group per value, with their captions.
void draw_views(std::ostream& out, const Layout& layout, const BlockViews& views, const Sheet& s,
                double unit) {
  std::vector<std::vector<const BlockViews::Cell*>> by_value(layout.legend.size());
  for (const BlockViews::Cell& v : views.cells) by_value[v.value].push_back(&v);
  for (const LegendEntry& entry : layout.legend) {
    out << fmt::format(
        "<g id=\"value-{}\" class=\"value\" data-value=\"{}\" data-label=\"{}\" data-count=\"{}\" "
        "fill=\"{}\" stroke=\"#222\" stroke-width=\"{}\">\n",
        entry.value, entry.value, escape(entry.label), entry.value ? entry.count : 0,
        hex_colour(entry.colour), mm(unit * 0.03));
    // Each cell names the blocks it stands for; the plan's cell takes its top block's ID (every
    // block lies under exactly one plan cell, so IDs stay unique).
    for (const BlockViews::Cell* v : by_value[entry.value]) {
      std::string ids;
      for (const std::string& id : v->elements) ids += (ids.empty() ? "" : " ") + id;
      out << fmt::format("<path {}class=\"element\" data-elements=\"{}\" d=\"{}\"/>\n",
                         v->plan ? fmt::format("id=\"{}\" ", v->elements.front()) : "", ids,
                         rect_path(s, v->rect));
    }
    out << "</g>\n";
  }
  for (const auto& [text, area] : views.captions)
    out << fmt::format(
        "<text class=\"caption\" x=\"{}\" y=\"{}\" font-size=\"{}\" fill=\"#222\">{}</text>\n",
        mm(s.x(area.x)), mm(s.y(area.top()) - unit * 0.4), mm(unit * 0.8), escape(text));
}

// Park: one group per element type, surfaces first (whole-cell ones merged), objects on top.
// Beyond the outline is paper, not surface: white over the joints, and the outline drawn.
void draw_outside(std::ostream& out, const Layout& layout, const Sheet& s, double unit) {
  if (!layout.outside.empty() || !layout.cut_away.empty()) {
    out << "<g id=\"outside\" class=\"outside\" fill=\"#ffffff\">\n";
    for (const Rect& o : layout.outside)
      out << fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>\n", mm(s.x(o.x)),
                         mm(s.y(o.y, o.h)), mm(o.w), mm(o.h));
    for (const Outline& o : layout.cut_away) {  // beyond sloping edges, in sloping zones
      std::string d;
      for (const Ring& ring : o.rings) d += polygon_path(s, ring);
      out << fmt::format("<path fill-rule=\"evenodd\" d=\"{}\"/>\n", d);
    }
    out << "</g>\n";
  }
  if (!layout.outline.empty()) {
    out << fmt::format(
        "<path id=\"outline\" class=\"outline\" d=\"{}\" fill=\"none\" stroke=\"#222\" "
        "stroke-width=\"{}\"/>\n",
        shape_path(s, layout.outline, layout.outline_contour), mm(unit * 0.08));
  }
}

void draw_park(std::ostream& out, const Layout& layout, const Sheet& s, double unit) {
  std::vector<std::string> types;
  std::map<std::string, std::vector<const Element*>> by_type;
  for (const Element& e : layout.elements) {
    stop_point();
    if (!by_type.count(e.type)) types.push_back(e.type);
    by_type[e.type].push_back(&e);
  }
  std::stable_sort(types.begin(), types.end(), [&](const std::string& a, const std::string& b) {
    return !by_type[a].front()->circle && by_type[a].front()->shape.size() == 1 &&
           by_type[a].front()->shape[0].w >= by_type[a].front()->nominal.w - 1e-6 &&
           !(by_type[b].front()->shape.size() == 1 &&
             by_type[b].front()->shape[0].w >= by_type[b].front()->nominal.w - 1e-6);
  });
  for (const std::string& type : types) {
    const auto& list = by_type[type];
    std::string id = type;
    for (char& c : id)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '-';
    out << fmt::format(
        "<g id=\"type-{}\" class=\"element-type\" data-type=\"{}\" data-count=\"{}\" "
        "fill=\"{}\">\n",
        id, escape(type), list.size(), hex_colour(list.front()->colour));
    // Whole-cell surfaces of this type merge into rectangles; the rest are drawn one by one.
    std::vector<int> grid(static_cast<size_t>(layout.rows * layout.columns), -1);
    std::vector<const Element*> at(grid.size(), nullptr);
    for (const Element* e : list) {
      const bool whole = !e->circle && e->shape.size() == 1 && !e->cut &&
                         std::fabs(e->shape[0].w - e->nominal.w) < 1e-6 &&
                         std::fabs(e->shape[0].h - e->nominal.h) < 1e-6;
      if (whole) {
        const size_t i = static_cast<size_t>(e->row * layout.columns + e->column);
        grid[i] = 0;
        at[i] = e;
        continue;
      }
      if (e->circle) {
        out << fmt::format(
            "<circle id=\"{}\" cx=\"{}\" cy=\"{}\" r=\"{}\" fill-opacity=\"0.85\" "
            "stroke=\"#1d3b26\" stroke-width=\"{}\"/>\n",
            e->id, mm(s.x(e->circle->cx)), mm(s.y(e->circle->cy)), mm(e->circle->d / 2),
            mm(unit * 0.04));
        if (const std::optional<Rect> pit = tree_pit(layout, *e))  // dashed, as dug
          out << fmt::format(
              "<rect class=\"tree-pit\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" "
              "fill=\"none\" stroke=\"#222\" stroke-width=\"{}\" stroke-dasharray=\"{} {}\"/>\n",
              mm(s.x(pit->x)), mm(s.y(pit->top())), mm(pit->w), mm(pit->h), mm(unit * 0.04),
              mm(unit * 0.3), mm(unit * 0.2));
        continue;
      }
      std::string d;
      for (const Rect& r : e->shape) d += rect_path(s, r);
      if (e->outline)  // cut along a sloping or curved edge
        for (const Ring& ring : e->outline->rings) d += polygon_path(s, ring);
      out << fmt::format(
          "<path id=\"{}\" d=\"{}\"{}{}/>\n", e->id, d, e->outline ? " fill-rule=\"evenodd\"" : "",
          e->shape.size() == 1 && e->shape[0].w < e->nominal.w - 1e-6 &&
                  e->shape[0].h < e->nominal.h - 1e-6
              ? fmt::format(" stroke=\"#3a2a1a\" stroke-width=\"{}\"", mm(unit * 0.04))
              : "");
      if (const auto back = back_edge(*e))  // a bench's backrest: the way it faces reads
        out << fmt::format(
            "<line class=\"back\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#222\" "
            "stroke-width=\"{}\"/>\n",
            mm(s.x((*back)[0][0])), mm(s.y((*back)[0][1])), mm(s.x((*back)[1][0])),
            mm(s.y((*back)[1][1])), mm(unit * 0.12));
    }
    for (const GridRect& g : merge_runs(grid, layout.rows, layout.columns)) {
      write_merged(out, s, layout, at, g);
    }
    out << "</g>\n";
  }
  draw_outside(out, layout, s, unit);
}

// The grid's elements: uncut ones merged into runs, cut ones alone, and the joints over them.
void draw_grid_modules(std::ostream& out, const Layout& layout, const Sheet& s) {
  const double W = layout.width, H = layout.height;
  const size_t values = layout.legend.size();
  // Uncut elements on the grid are merged; cut ones are drawn alone.
  std::vector<int> grid(static_cast<size_t>(layout.rows * layout.columns), -1);
  std::vector<std::vector<const Element*>> cut(values);
  std::vector<const Element*> at(grid.size(), nullptr);
  for (const Element& e : layout.elements) {
    stop_point();
    const size_t i = static_cast<size_t>(e.row * layout.columns + e.column);
    at[i] = &e;
    if (e.cut)
      cut[e.value].push_back(&e);
    else
      grid[i] = static_cast<int>(e.value);
  }
  const bool bonded = layout.bond > 0;  // courses do not line up
  const std::vector<GridRect> merged = merge_runs(grid, layout.rows, layout.columns, !bonded);
  size_t next = 0;
  for (const LegendEntry& entry : layout.legend) {
    const std::string fill = layout.combine == Combine::keep
                                 ? fmt::format("url(#parts-{})", entry.value)
                                 : hex_colour(entry.colour);
    out << value_group(entry, fill);
    for (; next < merged.size() && merged[next].value == static_cast<int>(entry.value); ++next) {
      const GridRect& g = merged[next];
      write_merged(out, s, layout, at, g);
    }
    for (const Element* e : cut[entry.value]) {
      std::string d;
      for (const Rect& r : e->shape) d += rect_path(s, r);
      if (e->outline)  // cut along a sloping or curved edge
        for (const Ring& ring : e->outline->rings) d += polygon_path(s, ring);
      out << fmt::format("<path id=\"{}\" class=\"cut\" d=\"{}\"{} data-count=\"1\"/>\n", e->id, d,
                         e->outline ? " fill-rule=\"evenodd\"" : "");
    }
    out << "</g>\n";
  }

  // Joints over the merged fills: one path of strips.
  if (layout.joint > 0) {
    std::string d;
    if (bonded) {  // each course's own: after every element but the last along the course
      for (const Element& e : layout.elements) {
        stop_point();
        const bool right = from_right(layout.origin);
        const double x = right ? e.nominal.x - layout.joint : e.nominal.right();
        const Rect joint = clip(Rect{x, e.nominal.y, layout.joint, e.nominal.h}, W, H);
        if (joint.area() > 0) d += rect_path(s, joint);
      }
    } else {
      for (int64_t c = 1; c < layout.columns; ++c) {
        const double x = layout.cell_edge_x(layout.view.origin[0] + c) - layout.joint / 2;
        d += rect_path(s, Rect{x, 0, layout.joint, H});
      }
    }
    for (int64_t r = 1; r < layout.rows; ++r) {
      const double y = layout.cell_edge_y(layout.view.origin[1] + r) - layout.joint / 2;
      d += rect_path(s, Rect{0, y, W, layout.joint});
    }
    if (!d.empty())
      out << fmt::format("<path id=\"joints\" class=\"joint\" fill=\"{}\" d=\"{}\"/>\n",
                         hex_colour(layout.joint_colour), d);
  }
}

// A pattern's units (herringbone, basketweave, hexagons): the surface in the joints' colour,
// then each unit as its own polygon in its value's group.
void draw_pattern_units(std::ostream& out, const Layout& layout, const Sheet& s) {
  if (layout.joint > 0) {
    std::string d;
    for (const Outline& o :
         surfaced(Rect{0, 0, layout.width, layout.height}, layout.holes(), layout.cut_away))
      for (const Ring& ring : o.rings) d += polygon_path(s, ring);
    out << fmt::format(
        "<path id=\"joints\" class=\"joint\" fill=\"{}\" fill-rule=\"evenodd\" d=\"{}\"/>\n",
        hex_colour(layout.joint_colour), d);
  }
  const auto by_value = elements_by_value(layout);
  for (const LegendEntry& entry : layout.legend) {
    out << value_group(entry, hex_colour(entry.colour));
    for (const Element* e : by_value[entry.value]) {
      stop_point();
      std::string d;
      for (const Ring& ring : e->outline->rings) d += polygon_path(s, ring);
      out << fmt::format(
          "<path id=\"{}\" class=\"{}\" fill-rule=\"evenodd\" d=\"{}\" "
          "data-count=\"1\"/>\n",
          e->id, e->cut ? "cut" : "unit", d);
    }
    out << "</g>\n";
  }
}

void draw_modules(std::ostream& out, const Layout& layout, const Sheet& s, double unit) {
  if (layout.pattern != LayingPattern::grid)
    draw_pattern_units(out, layout, s);
  else
    draw_grid_modules(out, layout, s);
  draw_outside(out, layout, s, unit);
  if (!layout.openings.empty()) {
    out << fmt::format(
        "<g id=\"openings\" class=\"opening\" fill=\"#dfeaf2\" stroke=\"#44515c\" "
        "stroke-width=\"{}\">\n",
        mm(unit * 0.08));
    for (size_t i = 0; i < layout.openings.size(); ++i) {
      const Rect& o = layout.openings[i];
      out << fmt::format("<rect id=\"opening-{}\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>\n",
                         i, mm(s.x(o.x)), mm(s.y(o.y, o.h)), mm(o.w), mm(o.h));
    }
    out << "</g>\n";
  }
}

// The legend under the drawing from `top`: one row a product (a park: a material as planted
// and built), a swatch and its line.
void write_legend(std::ostream& out, const Layout& layout, double top, double legend_room,
                  double margin, double unit) {
  // One row a product (a park: a material as planted and built): its value, fill and text.
  struct Row {
    uint32_t value;
    std::vector<std::string> fills;  // side by side: each look of the product
    std::string text;
  };
  std::vector<Row> rows;
  const bool striped = layout.combine == Combine::keep && layout.kind->ground() != Ground::sheet;
  if (layout.kind->depiction() == Depiction::objects) {
    for (const MaterialLine& l : material_lines(layout))
      rows.push_back({0, {hex_colour(l.colour)}, l.text()});
  } else {
    for (const LegendLine& l : legend_lines(layout.legend)) {
      std::vector<std::string> fills;
      for (const LegendEntry* look : l.looks)
        fills.push_back(striped ? fmt::format("url(#parts-{})", look->value)
                                : hex_colour(look->colour));
      rows.push_back(
          {l.entry->value, fills,
           fmt::format("{} {}: {}", l.values, l.entry->label, legend_count(layout, l.count))});
    }
  }
  // The text shrinks, when its longest line would run into the title block (`legend_room`
  // from the legend's text), to about 0.6 em a character.
  size_t longest_entry = 0;
  for (const Row& r : rows) longest_entry = std::max(longest_entry, r.text.size());
  const double legend_font =
      std::min(unit, legend_room / (0.6 * static_cast<double>(std::max<size_t>(longest_entry, 1))));
  out << fmt::format("<g id=\"legend\" font-size=\"{}\" fill=\"#222\">\n", mm(legend_font));
  size_t shown = 0;
  for (const Row& r : rows) {
    if (shown == 16) break;
    const double y = top + unit * 1.6 * static_cast<double>(shown++);
    const double w = unit * 2 / static_cast<double>(r.fills.size());
    std::string swatches;
    for (size_t i = 0; i < r.fills.size(); ++i)
      swatches += fmt::format(
          "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" stroke=\"#222\" "
          "stroke-width=\"{}\"/>",
          mm(margin + w * static_cast<double>(i)), mm(y), mm(w), mm(unit * 1.2), r.fills[i],
          mm(unit * 0.05));
    out << fmt::format(
        "<g class=\"legend-entry\" data-value=\"{}\">{}<text x=\"{}\" y=\"{}\">{}</text></g>\n",
        r.value, swatches, mm(margin + unit * 2.6), mm(y + unit), escape(r.text));
  }
  out << "</g>\n";
}

void draw_overlays_and_sheet(std::ostream& out, const Layout& layout, const Sheet& s, double unit,
                             double margin) {
  const Provenance& source = layout.source;
  const DrawingKeys& drawing = layout.drawing;
  const double W = layout.width, H = layout.height;
  // Overlays.
  if (drawing.stage_grid) {
    out << "<g id=\"stage-grid\" class=\"overlay\" fill=\"none\" stroke=\"#d6336c\">\n";
    const Lattice& l = source.lattice;
    for (int k = 0; k < l.stages; ++k) {
      const int64_t step = static_cast<int64_t>(l.side_in_cells(k));
      std::string d;
      const Box& v = layout.view;
      for (int64_t x = (v.origin[0] + step - 1) / step * step; x <= v.origin[0] + v.size[0];
           x += step) {
        const double px = layout.cell_edge_x(x);
        d += fmt::format("M{} {}V{}", mm(s.x(px)), mm(s.y(0)), mm(s.y(H)));
      }
      for (int64_t y = (v.origin[1] + step - 1) / step * step; y <= v.origin[1] + v.size[1];
           y += step) {
        const double py = layout.cell_edge_y(y);
        d += fmt::format("M{} {}H{}", mm(s.x(0)), mm(s.y(py)), mm(s.x(W)));
      }
      out << fmt::format(
          "<path class=\"stage-{}\" data-stage=\"{}\" stroke-width=\"{}\" "
          "stroke-opacity=\"0.8\" d=\"{}\"/>\n",
          k, k, mm(unit * 0.25 / (k + 1)), d);
    }
    out << "</g>\n";
  }
  if (drawing.highlight) {
    const Box& w = *drawing.highlight;
    const double x0 = layout.cell_edge_x(w.origin[0]),
                 x1 = layout.cell_edge_x(w.origin[0] + w.size[0]);
    const double y0 = layout.cell_edge_y(w.origin[1]),
                 y1 = layout.cell_edge_y(w.origin[1] + w.size[1]);
    out << fmt::format(
        "<rect id=\"window\" class=\"overlay\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" "
        "fill=\"none\" stroke=\"#1864ab\" stroke-width=\"{}\" stroke-dasharray=\"{} {}\" "
        "data-cells=\"{},{},{},{}\"/>\n",
        mm(s.x(std::min(x0, x1))), mm(s.y(std::min(y0, y1), std::fabs(y1 - y0))),
        mm(std::fabs(x1 - x0)), mm(std::fabs(y1 - y0)), mm(unit * 0.3), mm(unit), mm(unit * 0.5),
        w.origin[0], w.origin[1], w.size[0], w.size[1]);
  }

  // Zones: each outlined and named, value zones dashed.
  if (!layout.zones.empty()) {
    out << fmt::format("<g id=\"zones\" class=\"overlay\" fill=\"none\" font-size=\"{}\">\n",
                       mm(unit * 0.8));
    for (const ZoneCount& z : layout.zones) {
      const bool value = z.rule == ZoneRule::value;
      out << fmt::format(
          "<g class=\"zone\" data-name=\"{}\" data-rule=\"{}\"><path d=\"{}\" stroke=\"{}\" "
          "stroke-width=\"{}\"{}/><text x=\"{}\" y=\"{}\" fill=\"#222\" stroke=\"#fff\" "
          "stroke-width=\"{}\" paint-order=\"stroke\">{}</text></g>\n",
          escape(z.name), value ? "value" : "exclude", shape_path(s, z.polygon, z.contour),
          value ? "#222" : "#44515c", mm(unit * 0.12),
          value ? fmt::format(" stroke-dasharray=\"{} {}\"", mm(unit * 0.6), mm(unit * 0.4)) : "",
          mm(s.x(z.polygon[0][0]) + unit * 0.4), mm(s.y(z.polygon[0][1]) - unit * 0.4),
          mm(unit * 0.2), escape(value ? fmt::format("{} (value {})", z.name, z.value) : z.name));
    }
    out << "</g>\n";
  }

  // Legend and title block, under the drawing.
  const double top = margin * 1.5 + H;
  const double tx = margin + W * 0.42;  // the title block's left edge
  write_legend(out, layout, top, tx - unit * 1.2 - (margin + unit * 2.6), margin, unit);
  const std::vector<std::string> lines = title_lines(layout);
  // Sized to fit the longest line at about half an em per character.
  std::vector<std::string> all = lines;
  for (const std::string& note : layout.notes) all.push_back("note: " + note);
  size_t longest = 0;
  for (const std::string& l : all) longest = std::max(longest, l.size());
  const double box_w = W + margin - (tx - unit * 0.6);
  const double font = std::min(unit * 0.8, box_w / (0.62 * static_cast<double>(longest) + 1));
  out << fmt::format("<g id=\"title-block\" font-size=\"{}\" fill=\"#222\">\n", mm(font));
  out << fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" "
      "stroke=\"#222\" stroke-width=\"{}\"/>\n",
      mm(tx - unit * 0.6), mm(top - unit * 0.2), mm(box_w),
      mm(font * 1.5 * all.size() + unit * 0.8), mm(unit * 0.05));
  for (size_t i = 0; i < all.size(); ++i)
    out << fmt::format("<text{} x=\"{}\" y=\"{}\"{}>{}</text>\n",
                       i >= lines.size() ? " class=\"note\"" : "", mm(tx),
                       mm(top + unit * 0.4 + font * (1 + 1.5 * i)),
                       i == 0 ? " font-weight=\"bold\"" : "", escape(all[i]));
  out << "</g>\n</svg>\n";
}

}  // namespace

void write_layout_svg(std::ostream& out, const Layout& layout) {
  const Provenance& source = layout.source;
  const double W = layout.width, H = layout.height;
  const double unit = std::max(W, H) / 60;  // text and line sizes follow the drawing
  const double margin = unit * 2;
  const size_t values = layout.legend.size();
  const double legend_rows = static_cast<double>(std::min<size_t>(values, 16));
  const double title_rows = 5 + static_cast<double>(layout.notes.size());
  const double band = unit * (2 + std::max(1.6 * legend_rows, 1.2 * title_rows + 1));
  const Sheet s{margin, H};
  const double sheet_w = W + 2 * margin, sheet_h = H + 2 * margin + band;

  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{}mm\" height=\"{}mm\" "
      "viewBox=\"0 0 {} {}\" font-family=\"Helvetica, Arial, sans-serif\">\n",
      mm(sheet_w), mm(sheet_h), mm(sheet_w), mm(sheet_h));
  out << "<title>" << escape(source.recipe) << " - seed " << source.seed << "</title>\n";
  out << "<desc>Generated by curdle. Units: millimetres; the layout's origin is the bottom-left "
         "corner of its drawing area.</desc>\n";

  // Patterns for keep mode: each curd present keeps its own stripe of the element, counted
  // from the side laying starts from (as keep_stripes gives them to the PNG and the glTF).
  // (A sheet's openings in keep mode are their union, not stripes.)
  const bool striped = layout.combine == Combine::keep && layout.kind->ground() != Ground::sheet;
  if (striped) {
    out << "<defs>\n";
    const double pw = layout.module_w + layout.joint, ph = layout.module_h + layout.joint;
    const bool right = from_right(layout.origin);
    const bool top = from_top(layout.origin);
    // The pattern's tiles start where the grid does: the origin corner less the shift.
    const double ox = s.x(right ? W + layout.shift[0] : -layout.shift[0]);
    const double oy = s.y(top ? H + layout.joint + layout.shift[1] : -layout.shift[1]);
    for (const LegendEntry& e : layout.legend) {
      out << fmt::format(
          "<pattern id=\"parts-{}\" patternUnits=\"userSpaceOnUse\" x=\"{}\" y=\"{}\" width=\"{}\" "
          "height=\"{}\">",
          e.value, mm(ox), mm(oy - ph), mm(pw), mm(ph));
      const double part = layout.module_w / static_cast<double>(e.parts.size());
      for (size_t i = 0; i < e.parts.size(); ++i)
        out << fmt::format("<rect x=\"{}\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"{}\"/>",
                           mm(right ? pw - (i + 1) * part : i * part), mm(part), mm(ph),
                           hex_colour(e.parts[i]));
      out << "</pattern>\n";
    }
    out << "</defs>\n";
  }

  out << fmt::format("<g id=\"layout\" class=\"{}\" data-element-type=\"{}\">\n",
                     escape(std::string(layout.kind->name())), escape(layout.element_type));
  const bool sheet = layout.kind->ground() == Ground::sheet;
  out << fmt::format(
      "<rect id=\"background\" class=\"{}\" x=\"{}\" y=\"{}\" width=\"{}\" "
      "height=\"{}\" fill=\"{}\"{}/>\n",
      sheet ? "sheet" : "joint", mm(s.x(0)), mm(s.y(0, H)), mm(W), mm(H),
      hex_colour(ground_colour(layout)),
      sheet ? fmt::format(" stroke=\"#222\" stroke-width=\"{}\"", mm(unit * 0.05)) : "");

  switch (layout.kind->depiction()) {
    case Depiction::shapes:
      draw_openings(out, layout, s);
      draw_outside(out, layout, s, unit);
      break;
    case Depiction::views:
      if (layout.block_views) draw_views(out, layout, *layout.block_views, s, unit);
      break;
    case Depiction::objects:
      draw_park(out, layout, s, unit);
      break;
    case Depiction::grid:
      draw_modules(out, layout, s, unit);
      break;
  }
  out << "</g>\n";
  draw_overlays_and_sheet(out, layout, s, unit, margin);
}

}  // namespace curdle
