#include "export/drawing/course_marks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "layout/gauge.h"

namespace curdle::sheet_drawing {
namespace {

constexpr double kMarkTextMm = 1.8;

std::string length_text(double mm) { return fmt::format("{:g}", std::round(mm * 10) / 10); }

}  // namespace

void draw_course_numbers(cairo_t* cr, const InstallerPlan& plan, const LayingExtents& extents,
                         const View& v) {
  const double B = v.top + plan.viewport[1];
  // A coursed set numbers courses and columns alone (no IDs carry R and C), under headings.
  const bool coursed = plan.coursed;
  const std::string row_prefix = coursed ? "" : "R", column_prefix = coursed ? "" : "C";
  colour(cr, kRed);
  if (coursed) {
    text(cr, v.left - 10, v.top + plan.viewport[1] / 2, "course", 2, Align::centre, true);
    text(cr, v.left - 1.5, B + 4.5, "column", 2, Align::right);
  }
  double last = -1e300;
  for (const auto& [row, extent] : extents.rows) {
    const double mid = (extent.first + extent.second) / 2;
    if (mid < v.window.y || mid > v.window.top()) continue;
    const double y = v.y(mid);
    if (std::fabs(y - last) < 3.2) continue;
    last = y;
    text(cr, v.left - 1.5, y + 1.25, fmt::format("{}{}", row_prefix, row), 2.5, Align::right);
  }
  last = -1e300;
  for (const auto& [column, extent] : extents.columns) {
    const double mid = (extent.first + extent.second) / 2;
    if (mid < v.window.x || mid > v.window.right()) continue;
    const double x = v.x(mid);
    const std::string t = fmt::format("{}{}", column_prefix, column);
    if (std::fabs(x - last) < text_width(cr, t, 2.5) + 1.5) continue;
    last = x;
    text(cr, x, B + 4.5, t, 2.5, Align::centre);
  }
}

void draw_gauge_rod(cairo_t* cr, const Layout& layout, const LayingExtents& extents, const View& v,
                    const std::array<double, 2>& viewport) {
  const std::vector<GaugeMark> marks = gauge_marks(layout, extents, v.window);
  if (marks.empty()) return;
  // Beside the window, clear of its match line's caption; in the strip when it fills the frame.
  const double rod =
      std::min(v.x(std::min(v.window.right(), layout.width)), v.left + viewport[0]) + 6;
  colour(cr, kBlue);
  text(cr, rod - 1.2, v.top + viewport[1] + 9, "gauge, mm", kMarkTextMm, Align::left, false, true);
  cairo_set_line_width(cr, 0.2);
  cairo_move_to(cr, rod, v.y(marks.front().at));
  cairo_line_to(cr, rod, v.y(marks.back().at));
  cairo_stroke(cr);
  // Every course's bed is ticked; its height is written where the last one written is at
  // least a text's height below (at 1 : 20 a 75 mm course is 3.75 mm, every course).
  double last = 1e300;
  for (const GaugeMark& m : marks) {
    const double y = v.y(m.at);
    if (m.level) {
      // A storey level: across the frame, dashed, and named beside the rod.
      const double dash[] = {3, 1.5};
      cairo_set_dash(cr, dash, 2, 0);
      cairo_move_to(cr, v.left, y);
      cairo_line_to(cr, rod + 4, y);
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
      text_on_halo(cr, rod + 1, y - 0.6, m.label, kMarkTextMm);
      last = y - kMarkTextMm - 0.8;
      continue;
    }
    cairo_move_to(cr, rod - 1.2, y);
    cairo_line_to(cr, rod + 1.2, y);
    cairo_stroke(cr);
    if (last - y >= kMarkTextMm + 0.6) {
      text(cr, rod + 2, y + kMarkTextMm / 2, m.label, kMarkTextMm);
      last = y;
    }
  }
}

void draw_dimension_chain(cairo_t* cr, const Layout& layout, const View& v,
                          const std::array<double, 2>& viewport) {
  const std::vector<double> stops = dimension_stops(layout, v.window);
  if (stops.size() < 2) return;
  const double y = v.top + viewport[1] + 13;  // under the column numbers
  colour(cr, kBlue);
  cairo_set_line_width(cr, 0.2);
  cairo_move_to(cr, v.x(stops.front()), y);
  cairo_line_to(cr, v.x(stops.back()), y);
  cairo_stroke(cr);
  for (const double s : stops) {  // ticks, oblique as architects draw them
    cairo_move_to(cr, v.x(s), y - 2.5);
    cairo_line_to(cr, v.x(s), y + 1.5);
    cairo_move_to(cr, v.x(s) - 0.8, y + 0.8);
    cairo_line_to(cr, v.x(s) + 0.8, y - 0.8);
    cairo_stroke(cr);
  }
  for (size_t i = 0; i + 1 < stops.size(); ++i) {
    const std::string t = length_text(stops[i + 1] - stops[i]);
    const double room = v.x(stops[i + 1]) - v.x(stops[i]);
    // A length too short for its text is written under its stretch.
    const bool fits = text_width(cr, t, kMarkTextMm) + 1 <= room;
    text(cr, (v.x(stops[i]) + v.x(stops[i + 1])) / 2, fits ? y - 0.8 : y + 3.6, t, kMarkTextMm,
         Align::centre);
  }
  text(cr, v.x(stops.front()) - 1.5, y + 0.8, fmt::format("x {}", length_text(stops.front())),
       kMarkTextMm, Align::right);
}

}  // namespace curdle::sheet_drawing
