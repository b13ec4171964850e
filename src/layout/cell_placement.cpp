#include "layout/cell_placement.h"

#include <cmath>
#include <map>

#include "layout/builder.h"
#include "layout/laying_pattern.h"

namespace curdle {

std::array<double, 2> surface_extent(const LayoutSpec& spec, const Box& view) {
  if (spec.size) return *spec.size;
  const double pitch_w = spec.module_w + spec.joint, pitch_h = spec.module_h + spec.joint;
  return {static_cast<double>(view.size[0]) * pitch_w - spec.joint - spec.shift[0] -
              largest_offset(spec, view.size[1]),
          static_cast<double>(view.size[1]) * pitch_h - spec.joint - spec.shift[1]};
}

CellPlacement cell_placement(const LayoutSpec& spec, const Box& view) {
  return spec.kind->cell_placement(spec, view);
}

namespace {

// A pattern's cells at its own pitch, placed where its units' centres lie on average (exact for
// basketweave squares, within half a unit for hexagons and the 45° herringbone; the 90°
// herringbone's cells run along its diagonals, which no map along x and y follows).
CellPlacement pattern_cell_placement(const LayoutSpec& spec, const Box& view) {
  CellPlacement p;
  const auto extent = surface_extent(spec, view);
  const auto pitch = pattern_cell_pitch(spec.pattern, spec.module_w, spec.module_h, spec.joint);
  p.scale = {pitch[0], pitch[1], 1};
  const std::vector<PatternUnit> units =
      pattern_units(spec.pattern, spec.module_w, spec.module_h, spec.joint, extent[0], extent[1]);
  const bool right = from_right(spec.origin), top = from_top(spec.origin);
  // Each cell's units' centres (a basketweave square's n, only where all n are laid).
  std::map<std::pair<int64_t, int64_t>, std::array<double, 3>> cells;  // sum x, sum y, units
  int most = 1;
  for (const PatternUnit& u : units) {
    auto& c = cells[{u.column, u.row}];
    for (const auto& [x, y] : u.ring) c[0] += x, c[1] += y;
    c[2] += static_cast<double>(u.ring.size());
    most = std::max(most, u.part);
  }
  double sum_x = 0, sum_y = 0, n = 0;
  for (const auto& [cell, c] : cells) {
    if (c[2] < most * 4 - 0.5) continue;  // a square with units left off (four corners a unit)
    const double cx = c[0] / c[2], cy = c[1] / c[2];
    const double i = static_cast<double>(right ? view.size[0] - 1 - cell.first : cell.first);
    const double j = static_cast<double>(top ? view.size[1] - 1 - cell.second : cell.second);
    sum_x +=
        (right ? extent[0] - cx : cx) - (static_cast<double>(view.origin[0]) + i + 0.5) * pitch[0];
    sum_y +=
        (top ? extent[1] - cy : cy) - (static_cast<double>(view.origin[1]) + j + 0.5) * pitch[1];
    n += 1;
  }
  n = std::max(n, 1.0);
  p.origin[0] = sum_x / n, p.origin[1] = sum_y / n;
  return p;
}

}  // namespace

CellPlacement grid_cell_placement(const LayoutSpec& spec, const Box& view) {
  if (spec.pattern != LayingPattern::grid && spec.size) return pattern_cell_placement(spec, view);
  CellPlacement p;
  const auto vx = static_cast<double>(view.origin[0]), vy = static_cast<double>(view.origin[1]);
  // builder.cpp: column c (from the origin corner) starts at c pitch - shift - course offset.
  const double pitch_w = spec.module_w + spec.joint, pitch_h = spec.module_h + spec.joint;
  const auto extent = surface_extent(spec, view);
  const auto columns = static_cast<double>(view.size[0]), rows = static_cast<double>(view.size[1]);
  const bool right = from_right(spec.origin), top = from_top(spec.origin);
  p.scale = {pitch_w, pitch_h, 1};
  p.origin[0] = -(vx + 0.5) * pitch_w +
                (right ? extent[0] - (columns - 1) * pitch_w + spec.shift[0] - spec.module_w / 2
                       : -spec.shift[0] + spec.module_w / 2);
  p.origin[1] = -(vy + 0.5) * pitch_h +
                (top ? extent[1] - (rows - 1) * pitch_h + spec.shift[1] - spec.module_h / 2
                     : -spec.shift[1] + spec.module_h / 2);
  if (spec.bond > 0) {
    const auto period = static_cast<int64_t>(std::llround(1 / spec.bond));
    for (int64_t r = 0; r < period; ++r)
      p.course_shift.push_back((right ? 1 : -1) * course_offset(spec, r));
    // Row r counted from the origin corner: y - vy from the bottom, the other way from the top.
    p.row_sign = top ? -1 : 1;
    p.row_base = top ? view.size[1] - 1 + view.origin[1] : -view.origin[1];
  }
  return p;
}

}  // namespace curdle
