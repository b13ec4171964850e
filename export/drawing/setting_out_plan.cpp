#include "export/drawing/setting_out_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "export/drawing/sheet_drawing.h"
#include "layout/contour.h"
#include "layout/curved_facade.h"
#include "layout/drawing_sheet.h"

namespace curdle::sheet_drawing {
namespace {

constexpr double kText = 1.8, kSmall = 1.4, kLine = 2.6;  // mm on paper

// A frame's outer face in plan, its arc in chords of at most 2 degrees.
std::vector<std::array<double, 2>> face_points(const SurfaceFrame& f) {
  if (f.bulge == 0) return {f.from, f.to};
  const Arc arc = arc_between({f.from[0], f.from[1], f.bulge}, {f.to[0], f.to[1], 0});
  const int n = std::max(2, static_cast<int>(std::ceil(std::fabs(arc.sweep) / 0.035)));
  std::vector<std::array<double, 2>> out;
  const double a0 = arc.start_angle();
  for (int k = 0; k <= n; ++k) {
    const double a = a0 + arc.sweep * k / n;
    out.push_back(
        {arc.centre[0] + arc.radius * std::cos(a), arc.centre[1] + arc.radius * std::sin(a)});
  }
  return out;
}

}  // namespace

bool draw_setting_out_plan(cairo_t* cr, const Layout& layout, double x, double y, double w,
                           double h) {
  const std::vector<CurvedFacade> arcs = curved_facades(layout);
  if (arcs.empty() || w < 60 || h < 30) return false;
  // The lines first, at the top of the box; the plan in what is left.
  std::vector<std::string> lines;
  for (const CurvedFacade& c : arcs) {
    lines.push_back(c.line);
    std::string offsets = fmt::format(
        "  offsets square to the chord from ({}, {}) to ({}, {}), "
        "mm at mm along it:",
        drawing_mm(c.from[0]), drawing_mm(c.from[1]), drawing_mm(c.to[0]), drawing_mm(c.to[1]));
    for (const ChordOffset& o : c.offsets)
      offsets += fmt::format(" {:.0f} at {:.0f};", o.offset, o.along);
    offsets.pop_back();
    lines.push_back(offsets);
    lines.push_back("  " + c.units);
  }
  lines = wrap_lines(cr, lines, w, kText, std::max<size_t>(3, static_cast<size_t>(h / 3 / kLine)));
  double bx0 = 1e300, by0 = 1e300, bx1 = -1e300, by1 = -1e300;
  for (const SurfaceFrame& f : layout.frames())
    for (const auto& p : face_points(f))
      bx0 = std::min(bx0, p[0]), by0 = std::min(by0, p[1]), bx1 = std::max(bx1, p[0]),
      by1 = std::max(by1, p[1]);
  const double top = y + kLine * static_cast<double>(lines.size() + 1) + 4;
  const double room_w = w - 30, room_h = y + h - top - 6;  // labels round the plan
  double scale = 0;
  for (const double s : standard_scales())
    if ((bx1 - bx0) / s <= room_w && (by1 - by0) / s <= room_h) {
      scale = s;
      break;
    }
  if (scale == 0 || room_h < 15) return false;
  colour(cr, kInk);
  text(cr, x, y + kText,
       fmt::format("setting-out plan of the curved façades, 1 : {:g}, north up; "
                   "mm from the datum (0, 0), x east, y north",
                   scale),
       kText, Align::left, false, true);
  for (size_t i = 0; i < lines.size(); ++i)
    text(cr, x, y + kText + kLine * static_cast<double>(i + 1), lines[i], kText);
  const double ox = x + 15 + (room_w - (bx1 - bx0) / scale) / 2;
  const double oy = top + (room_h - (by1 - by0) / scale) / 2;
  auto px = [&](double X) { return ox + (X - bx0) / scale; };
  auto py = [&](double Y) { return oy + (by1 - Y) / scale; };
  cairo_set_line_width(cr, 0.35);
  for (const SurfaceFrame& f : layout.frames()) {
    const auto points = face_points(f);
    cairo_move_to(cr, px(points[0][0]), py(points[0][1]));
    for (const auto& p : points) cairo_line_to(cr, px(p[0]), py(p[1]));
    cairo_stroke(cr);
  }
  for (const CurvedFacade& c : arcs) {
    const double ux = (c.to[0] - c.from[0]) / c.chord, uy = (c.to[1] - c.from[1]) / c.chord;
    // Square to the chord, towards the arc: towards the side the arc's middle lies on.
    const double mx = (c.from[0] + c.to[0]) / 2, my = (c.from[1] + c.to[1]) / 2;
    double nx = -uy, ny = ux;
    if ((c.centre[0] - mx) * nx + (c.centre[1] - my) * ny > 0) nx = -nx, ny = -ny;
    colour(cr, kBlue);
    cairo_set_line_width(cr, 0.18);
    const double dash[] = {1.2, 0.8};
    cairo_set_dash(cr, dash, 2, 0);
    cairo_move_to(cr, px(c.from[0]), py(c.from[1]));
    cairo_line_to(cr, px(c.to[0]), py(c.to[1]));
    cairo_stroke(cr);
    // The way to the centre from each end, 12 mm on paper, labelled where it points.
    for (const auto& end : {c.from, c.to}) {
      const double dx = c.centre[0] - end[0], dy = c.centre[1] - end[1];
      const double d = std::hypot(dx, dy), reach = std::min(d, 12 * scale);
      cairo_move_to(cr, px(end[0]), py(end[1]));
      cairo_line_to(cr, px(end[0] + dx / d * reach), py(end[1] + dy / d * reach));
      cairo_stroke(cr);
      if (reach < d)
        text(cr, px(end[0] + dx / d * reach) + 0.8, py(end[1] + dy / d * reach) + 0.6, "to centre",
             kSmall);
    }
    cairo_set_dash(cr, nullptr, 0, 0);
    for (const ChordOffset& o : c.offsets) {
      const double sx = c.from[0] + ux * o.along, sy = c.from[1] + uy * o.along;
      const double ax = sx + nx * o.offset, ay = sy + ny * o.offset;
      cairo_move_to(cr, px(sx), py(sy));
      cairo_line_to(cr, px(ax), py(ay));
      cairo_stroke(cr);
      cairo_arc(cr, px(sx), py(sy), 0.35, 0, 2 * M_PI);
      cairo_fill(cr);
      if (o.offset > 0.5)
        text(cr, (px(sx) + px(ax)) / 2 + 0.6, (py(sy) + py(ay)) / 2,
             fmt::format("{:.0f}", o.offset), kSmall);
    }
    colour(cr, kInk);
    text(cr, px(c.from[0]) - 1, py(c.from[1]) + 3,
         fmt::format("({}, {})", drawing_mm(c.from[0]), drawing_mm(c.from[1])), kSmall,
         Align::right);
    text(cr, px(c.to[0]) + 1, py(c.to[1]) + 3,
         fmt::format("({}, {})", drawing_mm(c.to[0]), drawing_mm(c.to[1])), kSmall);
    const double cx = std::clamp(px(c.centre[0]), x, x + w),
                 cy = std::clamp(py(c.centre[1]), top, y + h);
    const bool shown = cx == px(c.centre[0]) && cy == py(c.centre[1]);
    if (shown) {
      cairo_move_to(cr, cx - 1.5, cy), cairo_line_to(cr, cx + 1.5, cy);
      cairo_move_to(cr, cx, cy - 1.5), cairo_line_to(cr, cx, cy + 1.5);
      cairo_stroke(cr);
      text(cr, cx + 1.5, cy - 1,
           fmt::format("centre ({}, {}), R {}", drawing_mm(c.centre[0]), drawing_mm(c.centre[1]),
                       drawing_mm(c.radius)),
           kSmall);
    }
  }
  return true;
}

}  // namespace curdle::sheet_drawing
