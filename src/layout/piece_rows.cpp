#include "layout/piece_rows.h"

#include <fmt/format.h>

#include <cmath>

#include "curdle/palette.h"
#include "layout/framed_boxes.h"
#include "layout/piece.h"
#include "layout/union.h"
#include "layout/wkt.h"
#include "layout/zone.h"

namespace curdle {

std::string element_type_of(const Layout& layout, const Element& e) {
  if (!e.type.empty()) return e.type;
  if (e.form == ElementForm::opening) return "opening";
  // A building's unit turning a corner of another angle than 90° is a special, ordered as one.
  if (e.corner >= 0 && static_cast<size_t>(e.corner) < layout.frames().size()) {
    const double turn = layout.frames()[static_cast<size_t>(e.corner)].turn_at_end;
    const double angle = 180 - std::fabs(turn);
    if (std::fabs(angle - 90) >= 0.5)
      return fmt::format("{}, special for a {:.1f}° {} corner", layout.element_type, angle,
                         turn > 0 ? "outer" : "inner");
  }
  // A unit bent to a curved façade is ordered as one, by its developed width; headers, snap
  // headers, queen closers, cuts and half bats each on lines of their own.
  std::string type = layout.element_type;
  if (const SurfaceFrame* f = !layout.envelope ? nullptr : framed_facade(layout, e); f && f->bent)
    type += fmt::format(", bent to a {:.0f} mm radius", frame_radius(*f));
  switch (e.part) {
    case UnitPart::header:
      return type + ", header";
    case UnitPart::snap_header:
      return type + ", snap header (a half)";
    case UnitPart::queen_closer:
      return type + ", queen closer";
    case UnitPart::cut:
      return type + ", cut to fit";
    case UnitPart::half_bat:
      return type + ", half bat (stopped end)";
    case UnitPart::whole:
      break;
  }
  return type;
}

bool needs_backing(const Layout& layout, const Element& e) {
  return layout.backing() && e.form == ElementForm::piece && e.depth < layout.module_w - 1e-6;
}

// What an order line is bought as: the stock size, or the opening's diameter.
std::string stock_size_of(const Layout& layout, const Element& e) {
  if (e.circle) {
    std::string s = "D";  // appended: GCC 12 warns falsely on "D" + string
    s += mm_text(e.circle->d);
    return s;
  }
  if (e.outline && e.form == ElementForm::opening) return "merged opening";
  const bool block = e.form == ElementForm::block;  // its plan, then its storey
  const double h = block ? layout.level_height : e.stock_h;
  std::string s = mm_text(e.stock_w) + " x " + mm_text(h);
  if (block) s += " x " + mm_text(e.stock_h);
  return s;
}

std::string lot_text(const Layout& layout, const Element& e, size_t index) {
  // Openings of a perforated sheet are lotted by the fabrication sheet they are cut in (on a
  // building too: a sheet stands on one façade).
  if (e.sheet >= 0) return layout.sheets()[static_cast<size_t>(e.sheet)].id;
  // A building's units are lotted by façade (a corner unit by the face holding its middle), so
  // that lots.csv gives each façade's quantities, unless the recipe asks for lots by size.
  if (layout.envelope && layout.ordering.lot_rows == 0 && layout.ordering.lot_size == 0)
    return framed_facade(layout, e)->name;
  return std::to_string(lot_of(e, index, layout.ordering));
}

int64_t lot_of(const Element& e, size_t index, const OrderingKeys& ordering) {
  if (ordering.lot_rows > 0) return e.row / ordering.lot_rows + 1;
  if (ordering.lot_size > 0) return static_cast<int64_t>(index) / ordering.lot_size + 1;
  return 1;
}

ScheduleRow schedule_row(const Layout& layout, size_t index) {
  const Element& e = layout.elements[index];
  const Rect b = laid_bounds(e);
  ScheduleRow r{.id = e.id,
                .lot = lot_text(layout, e, index),
                .row = e.row,
                .column = e.column,
                .x = b.x,
                .y = b.y,
                .width = b.w,
                .height = b.h,
                .area = e.area(),
                .value = e.value,
                .element_type = element_type_of(layout, e),
                .colour = hex_colour(piece_colour(layout, e)),
                .material = piece_material(layout, e),
                .cut = e.cut};
  const bool block = e.form == ElementForm::block;
  if (block) {
    const int64_t level = e.cell_z - layout.view.origin[2];
    r.level = level;
    r.z = static_cast<double>(level) * layout.level_height;
    r.height = layout.level_height;
    r.depth = b.h;
  }
  if (e.stock_w * e.stock_h > 0) {
    r.stock_width = e.stock_w;
    r.stock_height = block ? layout.level_height : e.stock_h;
  }
  // Every piece's shape, so that a GIS reads the schedule as features: a cut piece's outline,
  // else its rectangle, or its circle within the layout's chord tolerance.
  r.outlines = piece_outlines(e);
  if (r.outlines.empty() && e.circle)
    r.outlines.push_back({{polygonise(*e.circle, layout.chord_tolerance)}, e.area()});
  else if (r.outlines.empty())
    r.outlines.push_back({{rect_polygon(b)}, b.area()});
  if (layout.envelope) {
    // On the strip, the closing corner's unit is one brick, not a box from end to end.
    const Rect strip = framed_strip_bounds(layout, e);
    r.width = strip.w;
    const BuildingPoint p = framed_centre(layout, e);
    r.strip_x = strip.x, r.strip_y = r.y;
    r.x = p[0], r.y = p[1], r.z = p[2];
    r.facade = framed_facade(layout, e)->name;
  }
  if (e.circle) {
    r.opening_x = e.circle->cx;
    r.opening_y = e.circle->cy;
    r.opening_diameter = e.circle->d;
  } else if (e.outline && e.form == ElementForm::opening) {
    r.opening_x = b.x + b.w / 2;
    r.opening_y = b.y + b.h / 2;
  }
  return r;
}

}  // namespace curdle
