#include "layout/installer_sheet_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "curdle/error.h"

namespace curdle {
namespace {

constexpr double kBandMm = 16;       // paper around the layout for labels beside edge pieces
constexpr double kNarrowBandMm = 8;  // at least a label's height and its gap

Rect spanning(double xa, double ya, double xb, double yb) {
  return {std::min(xa, xb), std::min(ya, yb), std::fabs(xb - xa), std::fabs(yb - ya)};
}

constexpr double kCaptionBandMm = 4.5;  // match-line captions' strip inside the sheet's edge

// Both sides of every edge two sheets share carry a caption naming the sheet beyond.
std::vector<MatchCaption> match_captions(const InstallerPlan& plan) {
  std::vector<MatchCaption> captions;
  const double band = kCaptionBandMm * plan.scale;
  auto index = [&](size_t r, size_t c) { return r * plan.grid_columns + c; };
  for (size_t i = 0; i < plan.sheets.size(); ++i) {
    const InstallerSheet& s = plan.sheets[i];
    const Rect& w = s.window;
    auto add = [&](size_t other, bool vertical, double edge_x, double edge_y) {
      MatchCaption c{i, other, {}, vertical};
      const double length =
          label_width_mm(match_caption_text(c).size(), kMatchCaptionMm) * plan.scale;
      c.box = centred_on(edge_x, edge_y, vertical ? band : length, vertical ? length : band);
      captions.push_back(c);
    };
    const double mx = w.x + w.w / 2, my = w.y + w.h / 2;
    if (s.column > 0) add(index(s.row, s.column - 1), true, w.x + band / 2, my);
    if (s.column + 1 < plan.grid_columns)
      add(index(s.row, s.column + 1), true, w.right() - band / 2, my);
    if (s.row > 0) add(index(s.row - 1, s.column), false, mx, w.y + band / 2);
    if (s.row + 1 < plan.grid_rows) add(index(s.row + 1, s.column), false, mx, w.top() - band / 2);
  }
  return captions;
}

// The start corner's dot, arrows and words (kStartDotMm...), as two strips outside the corner.
std::vector<Rect> start_corner_area(const Layout& layout, double scale) {
  if (!layout.kind->laid_from_corner()) return {};
  const double X = from_right(layout.origin) ? layout.width : 0;
  const double Y = from_top(layout.origin) ? layout.height : 0;
  const double sx = from_right(layout.origin) ? -1 : 1;  // into the layout
  const double sy = from_top(layout.origin) ? -1 : 1;
  const double near = (kStartDotMm - 1.5) * scale, far = (kStartDotMm + 2) * scale;
  const double words = label_width_mm(std::string_view(kStartText).size(), kStartTextMm);
  const double along = (kStartDotMm + kStartArrowMm + 2 + words) * scale;
  const double up = (kStartArrowMm + 1) * scale;
  return {spanning(X - sx * far, Y - sy * far, X + sx * along, Y - sy * near),
          spanning(X - sx * far, Y - sy * far, X - sx * near, Y + sy * up)};
}

// Where sheets meet along one axis, covering [from, to] with as few sheets as `length` allows,
// balanced by what they hold: each edge aims at the share of the pieces' centres its sheets
// should hold (a curved edge's sliver of pieces does not get a sheet to itself), and within a
// quarter of a sheet of that, and the slack the sheets leave, goes where the fewest pieces cross
// (a joint, so that pieces are not split by a match line and hold their own labels).
struct SheetEdges {
  std::vector<double> at;
  std::ptrdiff_t crossing = 0;  // pieces split by the edges between sheets
};
SheetEdges edges_between(const std::vector<std::pair<double, double>>& spans, double from,
                         double to, double length) {
  const double e = 1e-6;
  const auto count =
      std::max<size_t>(1, static_cast<size_t>(std::ceil((to - from) / length - 1e-9)));
  std::vector<double> lows, highs, centres;
  for (const auto& [lo, hi] : spans)
    lows.push_back(lo), highs.push_back(hi), centres.push_back((lo + hi) / 2);
  std::sort(lows.begin(), lows.end());
  std::sort(highs.begin(), highs.end());
  std::sort(centres.begin(), centres.end());
  auto crossing = [&](double c) {  // pieces that start before c and end after it
    return (std::lower_bound(lows.begin(), lows.end(), c - e) - lows.begin()) -
           (std::upper_bound(highs.begin(), highs.end(), c + e) - highs.begin());
  };
  std::vector<double> edges{from};
  std::ptrdiff_t split = 0;
  for (size_t i = 1; i < count; ++i) {
    // The rest must still fit, and this sheet no longer than a sheet.
    const double lo = to - static_cast<double>(count - i) * length;
    const double hi = edges.back() + length;
    double aim = from + (to - from) * static_cast<double>(i) / static_cast<double>(count);
    if (!centres.empty()) aim = centres[centres.size() * i / count];
    aim = std::clamp(aim, lo, hi);
    const double near_lo = std::max(lo, aim - length / 4), near_hi = std::min(hi, aim + length / 4);
    double best = aim;
    auto best_count = crossing(best);
    for (auto it = std::lower_bound(highs.begin(), highs.end(), near_lo);
         it != highs.end() && *it <= near_hi; ++it) {
      if (it != highs.begin() && *it == *(it - 1)) continue;
      const auto n = crossing(*it);
      if (n < best_count || (n == best_count && std::fabs(*it - aim) < std::fabs(best - aim)))
        best = *it, best_count = n;
    }
    edges.push_back(best);
    split += best_count;
  }
  edges.push_back(to);
  return {edges, split};
}

// The edges along one axis: with the full band of paper around the layout, or a narrower one
// where that lets the sheets meet at joints.
std::vector<double> sheet_edges(const std::vector<std::pair<double, double>>& spans, double size,
                                double length, double scale) {
  SheetEdges wide = edges_between(spans, -kBandMm * scale, size + kBandMm * scale, length);
  if (wide.crossing == 0) return wide.at;
  SheetEdges narrow =
      edges_between(spans, -kNarrowBandMm * scale, size + kNarrowBandMm * scale, length);
  return narrow.crossing < wide.crossing && narrow.at.size() <= wide.at.size() ? narrow.at
                                                                               : wide.at;
}

// A building's sheets along its strip: each façade its own run of sheets, so that a bricklayer
// carries one façade's set and every corner lies on a sheet's edge. The closing corner's unit,
// at both ends of the strip, is left to the façades it lies on.
std::vector<double> facade_edges(const std::vector<std::pair<double, double>>& spans,
                                 const Layout& layout, double length, double scale) {
  std::vector<double> xs;
  const std::vector<SurfaceFrame>& frames = layout.frames();
  for (size_t k = 0; k < frames.size(); ++k) {
    const SurfaceFrame& f = frames[k];
    const double from = k == 0 ? -kBandMm * scale : f.start;
    const double to = f.start + f.length + (k + 1 == frames.size() ? kBandMm * scale : 0);
    std::vector<std::pair<double, double>> own;
    for (const auto& s : spans) {
      const double centre = (s.first + s.second) / 2;
      if (centre >= f.start && centre < f.start + f.length && s.second - s.first < f.length)
        own.push_back(s);
    }
    const SheetEdges e = edges_between(own, from, to, length);
    xs.insert(xs.end(), e.at.begin() + (xs.empty() ? 0 : 1), e.at.end());
  }
  return xs;
}

size_t interval_of(const std::vector<double>& edges, double v) {
  const auto it = std::upper_bound(edges.begin() + 1, edges.end() - 1, v);
  return static_cast<size_t>(it - (edges.begin() + 1));
}

}  // namespace

// The grid of sheets at 1 : scale, with their match captions and the start corner.
void lay_sheets(const std::vector<InstallerPiece>& pieces, double scale, const Layout& layout,
                InstallerPlan& plan) {
  plan.scale = scale;
  std::vector<std::pair<double, double>> across, up;
  for (const InstallerPiece& p : pieces)
    across.emplace_back(p.bounds.x, p.bounds.right()), up.emplace_back(p.bounds.y, p.bounds.top());
  const std::vector<double> xs =
      !layout.envelope ? sheet_edges(across, layout.width, plan.viewport[0] * scale, scale)
                       : facade_edges(across, layout, plan.viewport[0] * scale, scale);
  const std::vector<double> ys = sheet_edges(up, layout.height, plan.viewport[1] * scale, scale);
  plan.grid_columns = xs.size() - 1;
  plan.grid_rows = ys.size() - 1;
  plan.sheets.clear();
  for (size_t r = 0; r < plan.grid_rows; ++r)
    for (size_t c = 0; c < plan.grid_columns; ++c)
      plan.sheets.push_back({r, c, {xs[c], ys[r], xs[c + 1] - xs[c], ys[r + 1] - ys[r]}});
  plan.captions = match_captions(plan);
  plan.start_corner = start_corner_area(layout, scale);
  plan.column_edges = xs, plan.row_edges = ys;
}

// More sheets than a site team can carry, and minutes of drawing: refused.
void check_named_scale(const Layout& layout, const InstallerPlan& plan, double scale) {
  auto sheets_at = [&](double n) {
    const double across = std::ceil(layout.width / (plan.viewport[0] * n));
    const double up = std::ceil(layout.height / (plan.viewport[1] * n));
    return std::max(1.0, across) * std::max(1.0, up);
  };
  const double sheets = sheets_at(scale);
  if (sheets <= static_cast<double>(kMostInstallerSheets)) return;
  double fits = 0;
  for (const double n : standard_scales())
    if (n > scale && sheets_at(n) <= static_cast<double>(kMostInstallerSheets)) {
      fits = n;
      break;
    }
  throw InputError(
      SourceLocation{"", 0, 0, "layout.installer_scale", ""},
      fmt::format("1 : {:g} on {} would take about {:.0f} installer's sheets; at most {}: choose "
                  "a smaller scale{} or larger paper (installer_paper), or leave the scale out "
                  "and curdle chooses one",
                  scale, plan.paper.name, sheets, kMostInstallerSheets,
                  fits > 0 ? fmt::format(" (1 : {:g} or beyond)", fits) : ""));
}

size_t sheet_holding(const InstallerPlan& plan, double x, double y) {
  return interval_of(plan.row_edges, y) * plan.grid_columns + interval_of(plan.column_edges, x);
}

}  // namespace curdle
