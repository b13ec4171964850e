#include "layout/cell_placement.h"

#include <cmath>

#include "layout/builder.h"

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

CellPlacement grid_cell_placement(const LayoutSpec& spec, const Box& view) {
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
