// Sheet 1's setting out (sheet_drawing.h): ordinate dimensions from the datum, arcs by their
// centres, free curves by offsets at their stations.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "export/drawing/sheet_drawing.h"
#include "layout/arc_setting_out.h"
#include "layout/curve_stations.h"
#include "layout/drawing_sheet.h"

namespace curdle::sheet_drawing {
namespace {

// Each arc of the outline and zones named where it runs (A1 and its radius at its middle), with
// a cross at its centre where that lies on the drawing; the list below the caption gives their
// centres, radii and ends.
void mark_arcs(cairo_t* cr, const Layout& layout, const View& v,
               const std::vector<SetOutArc>& arcs) {
  colour(cr, kBlue);
  cairo_set_line_width(cr, 0.15);
  for (const SetOutArc& a : arcs) {
    const double cx = a.arc.centre[0], cy = a.arc.centre[1];
    if (cx >= 0 && cy >= 0 && cx <= layout.width && cy <= layout.height) {
      cairo_move_to(cr, v.x(cx) - 1.2, v.y(cy)), cairo_line_to(cr, v.x(cx) + 1.2, v.y(cy));
      cairo_move_to(cr, v.x(cx), v.y(cy) - 1.2), cairo_line_to(cr, v.x(cx), v.y(cy) + 1.2);
      cairo_stroke(cr);
    }
    if (a.circle) {
      text(cr, v.x(cx) + 1.5, v.y(cy) + 2.8, "R " + drawing_mm(a.arc.radius), 1.6);
      continue;
    }
    // The arc's middle, with the label a little towards its centre.
    const double mid = a.arc.start_angle() + a.arc.sweep / 2;
    const double mx = cx + a.arc.radius * std::cos(mid), my = cy + a.arc.radius * std::sin(mid);
    const double in = 4 * v.scale;  // 4 mm on paper
    text(cr, v.x(mx - in * std::cos(mid)), v.y(my - in * std::sin(mid)),
         a.name + " R " + drawing_mm(a.arc.radius), 1.6, Align::centre);
  }
}

// A free curve's offsets: a thin dashed line along each station from the surface's edge
// nearer the curve to the curve, a dot there, and its ordinate from the datum beside the dot on
// the side away from that edge (clear of the edge's own ticks).
void mark_curve_offsets(cairo_t* cr, const Layout& layout, const View& v,
                        const std::vector<CurveStations>& curves) {
  constexpr double kOffsetText = 1.4, kOffsetGap = 0.8;  // mm on paper
  colour(cr, kBlue);
  cairo_set_line_width(cr, 0.1);
  const double dash[] = {0.6, 0.4};
  for (const CurveStations& c : curves) {
    double mean = 0;
    for (const auto& p : c.points) mean += c.along_x ? p[1] : p[0];
    mean /= static_cast<double>(std::max<size_t>(c.points.size(), 1));
    const double extent = c.along_x ? layout.height : layout.width;
    const bool far_edge = mean > extent / 2;  // the top (or right) edge is the nearer
    for (const auto& [x, y] : c.points) {
      cairo_set_dash(cr, dash, 2, 0);
      if (c.along_x)
        cairo_move_to(cr, v.x(x), v.y(far_edge ? extent : 0));
      else
        cairo_move_to(cr, v.x(far_edge ? extent : 0), v.y(y));
      cairo_line_to(cr, v.x(x), v.y(y));
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
      cairo_new_path(cr);
      cairo_arc(cr, v.x(x), v.y(y), 0.3, 0, 2 * M_PI);
      cairo_fill(cr);
      const std::string offset = drawing_mm(c.along_x ? y : x);
      const double w = text_width(cr, offset, kOffsetText);
      // On a halo: the pieces under it may be dark.
      if (c.along_x)  // reading up, below the dot from a top edge, above it from the bottom
        text_on_halo(cr, v.x(x) + kOffsetText / 2,
                     far_edge ? v.y(y) + kOffsetGap + w : v.y(y) - kOffsetGap, offset, kOffsetText,
                     Align::left, true);
      else  // left of the dot from a right edge, right of it from the left
        text_on_halo(cr, far_edge ? v.x(x) - kOffsetGap : v.x(x) + kOffsetGap,
                     v.y(y) + kOffsetText / 2, offset, kOffsetText,
                     far_edge ? Align::right : Align::left);
      colour(cr, kBlue);
    }
  }
}

// "C1: offsets in y every 2000 mm of x: 0: 2000, 2000: 1500, ..." under the caption.
std::string curve_line(const CurveStations& c, size_t index) {
  std::string line = fmt::format("C{}: a free curve, its {} every {} mm of {}:", index + 1,
                                 c.along_x ? "y" : "x", drawing_mm(c.step), c.along_x ? "x" : "y");
  for (size_t i = 0; i < c.points.size(); ++i) {
    const auto& [x, y] = c.points[i];
    line += fmt::format("{} {} at {}", i ? "," : "", drawing_mm(c.along_x ? y : x),
                        drawing_mm(c.along_x ? x : y));
  }
  return line;
}

}  // namespace

void setting_out(cairo_t* cr, const Layout& layout, const View& v, double bottom) {
  if (layout.width <= 0 || layout.height <= 0 || layout.block_views) return;
  std::vector<double> xs{0, layout.width}, ys{0, layout.height};
  auto add_ring = [&](const Polygon& ring) {
    for (const auto& p : ring) xs.push_back(p[0]), ys.push_back(p[1]);
  };
  // An arc is set out by its ends and centre (listed below), not by its chords' corners; a free
  // curve by offsets at its stations, drawn from the datum's edges to the curve.
  std::vector<CurveStations> curves;
  auto add_shape = [&](const Polygon& polygon, const Contour& contour) {
    const Contour shape = contour.empty() ? contour_of(polygon) : contour;
    const std::vector<CurveStations> free = curve_stations(shape);
    Contour corners;
    for (size_t i = 0; i < shape.size(); ++i)
      if (!inside_a_curve(free, i, shape.size())) corners.push_back(shape[i]);
    add_ring(set_out_points(corners, layout.width, layout.height));
    for (const CurveStations& c : free) {
      for (const auto& p : c.points) (c.along_x ? xs : ys).push_back(c.along_x ? p[0] : p[1]);
      curves.push_back(c);
    }
  };
  add_shape(layout.outline, layout.outline_contour);
  for (size_t i = 0; i < layout.openings_given; ++i) {
    const Rect& o = layout.openings[i];
    xs.insert(xs.end(), {o.x, o.right()}), ys.insert(ys.end(), {o.y, o.top()});
  }
  for (const ZoneCount& z : layout.zones) add_shape(z.polygon, z.contour);
  auto tidy = [](std::vector<double>& values, double high) {
    for (double& x : values) x = std::clamp(std::round(x * 10) / 10, 0.0, high);
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
  };
  tidy(xs, layout.width), tidy(ys, layout.height);
  // Away from the start corner, whose arrows and words lie along its two edges.
  const bool below = from_top(layout.origin), left = from_right(layout.origin);
  const double edge_y = below ? v.y(0) : v.y(layout.height);
  const double edge_x = left ? v.x(0) : v.x(layout.width);
  const double out_y = below ? 1 : -1, out_x = left ? -1 : 1;
  constexpr double kTickText = 1.6, kTickGap = 2.2;  // mm on paper
  colour(cr, kBlue);
  cairo_set_line_width(cr, 0.15);
  double last = -1e300;
  for (const double x : xs) {
    const double px = v.x(x);
    if (px - last < kTickGap && x != layout.width) continue;
    last = px;
    cairo_move_to(cr, px, edge_y + out_y * 0.8), cairo_line_to(cr, px, edge_y + out_y * 2.4);
    cairo_stroke(cr);
    // Read bottom to top, beyond the tick.
    const double ty = below ? edge_y + 3 + text_width(cr, drawing_mm(x), kTickText) : edge_y - 3;
    text(cr, px + kTickText / 2, ty, drawing_mm(x), kTickText, Align::left, true);
  }
  last = -1e300;
  for (const double y : ys) {
    const double py = v.y(y);
    if (last - py < kTickGap && y != layout.height && last > -1e299) continue;
    last = py;
    cairo_move_to(cr, edge_x + out_x * 0.8, py), cairo_line_to(cr, edge_x + out_x * 2.4, py);
    cairo_stroke(cr);
    text(cr, edge_x + out_x * 3, py + kTickText / 2, drawing_mm(y), kTickText,
         left ? Align::right : Align::left);
  }
  const char* corner = from_top(layout.origin)
                           ? (from_right(layout.origin) ? "top-right" : "top-left")
                       : from_right(layout.origin) ? "bottom-right"
                                                   : "bottom-left";
  const std::string caption = fmt::format(
      "setting out: mm from the datum (0, 0), the bottom-left corner; laying starts at the {} "
      "corner ({}, {})",
      corner, drawing_mm(from_right(layout.origin) ? layout.width : 0),
      drawing_mm(from_top(layout.origin) ? layout.height : 0));
  const double caption_y = below ? v.y(layout.height) - 2 : v.y(0) + 12;
  text(cr, v.x(0), caption_y, caption, 1.8);
  mark_curve_offsets(cr, layout, v, curves);
  const std::vector<SetOutArc> arcs = arcs_to_set_out(layout);
  if (arcs.empty() && curves.empty()) return;
  mark_arcs(cr, layout, v, arcs);
  // Up to three lines of arcs and curves under the caption (above it where the caption stands
  // on top).
  std::vector<std::string> lines;
  for (size_t i = 0; i < arcs.size() && lines.size() < 3; ++i) lines.push_back(arcs[i].line);
  if (arcs.size() > 3)
    lines.back() += fmt::format("; {} more in the DXF (layer OUTLINE and ZONES)", arcs.size() - 3);
  for (size_t i = 0; i < curves.size() && lines.size() < 3; ++i)
    lines.push_back(curve_line(curves[i], i));
  lines = fit_lines(cr, lines, std::max(40.0, v.x(layout.width) - v.x(0)), 1.6);
  for (size_t i = 0; i < lines.size(); ++i) {
    const double y = caption_y + (below ? -2.4 : 2.4) * static_cast<double>(i + 1);
    if (!below && y > bottom) break;  // the offsets stand on the drawing itself
    text(cr, v.x(0), y, lines[i], 1.6);
  }
}

}  // namespace curdle::sheet_drawing
