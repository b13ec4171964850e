#include "layout/installer_sheets.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <unordered_map>

#include "curdle/stop.h"
#include "layout/piece.h"

namespace curdle {
namespace {

constexpr double kRowStripMm = 14;    // row numbers, left of the frame
constexpr double kColumnStripMm = 8;  // column numbers, under the frame
constexpr double kBandMm = 16;        // paper around the layout for labels beside edge pieces
constexpr double kNarrowBandMm = 8;   // at least a label's height and its gap
constexpr size_t kScalesTried = 6;    // smaller scales tried when labels do not all find room

bool contains(const Rect& outer, const Rect& inner) {
  const double e = 1e-6;
  return inner.x >= outer.x - e && inner.y >= outer.y - e && inner.right() <= outer.right() + e &&
         inner.top() <= outer.top() + e;
}

// Label boxes already placed, found by a grid of buckets.
class PlacedLabels {
 public:
  explicit PlacedLabels(double bucket) : bucket_(bucket) {}
  bool collides(const Rect& r) const {
    bool hit = false;
    visit(r, [&](int64_t key) {
      const auto it = buckets_.find(key);
      if (it == buckets_.end()) return;
      for (const Rect& other : it->second)
        if (overlaps(other, r)) hit = true;
    });
    return hit;
  }
  void add(const Rect& r) {
    visit(r, [&](int64_t key) { buckets_[key].push_back(r); });
  }

 private:
  template <class F>
  void visit(const Rect& r, F&& f) const {
    const auto lo_x = static_cast<int64_t>(std::floor(r.x / bucket_));
    const auto hi_x = static_cast<int64_t>(std::floor(r.right() / bucket_));
    const auto lo_y = static_cast<int64_t>(std::floor(r.y / bucket_));
    const auto hi_y = static_cast<int64_t>(std::floor(r.top() / bucket_));
    for (int64_t y = lo_y; y <= hi_y; ++y)
      for (int64_t x = lo_x; x <= hi_x; ++x) f(y * 4000037 + x);
  }
  double bucket_;
  std::unordered_map<int64_t, std::vector<Rect>> buckets_;
};

Rect centred(double cx, double cy, double w, double h) { return {cx - w / 2, cy - h / 2, w, h}; }

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
      c.box = centred(edge_x, edge_y, vertical ? band : length, vertical ? length : band);
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

// Where sheets meet along one axis, covering [from, to] with as few sheets as `length` allows:
// each edge, within the slack the sheets leave, where the fewest pieces cross (a joint, so that
// pieces are not split by a match line and hold their own labels), nearest the even spacing.
struct SheetEdges {
  std::vector<double> at;
  std::ptrdiff_t crossing = 0;  // pieces split by the edges between sheets
};
SheetEdges edges_between(const std::vector<std::pair<double, double>>& spans, double from,
                         double to, double length) {
  const double e = 1e-6;
  const auto count =
      std::max<size_t>(1, static_cast<size_t>(std::ceil((to - from) / length - 1e-9)));
  std::vector<double> lows, highs;
  for (const auto& [lo, hi] : spans) lows.push_back(lo), highs.push_back(hi);
  std::sort(lows.begin(), lows.end());
  std::sort(highs.begin(), highs.end());
  auto crossing = [&](double c) {  // pieces that start before c and end after it
    return (std::lower_bound(lows.begin(), lows.end(), c - e) - lows.begin()) -
           (std::upper_bound(highs.begin(), highs.end(), c + e) - highs.begin());
  };
  std::vector<double> edges{from};
  std::ptrdiff_t split = 0;
  for (size_t i = 1; i < count; ++i) {
    const double even = from + (to - from) * static_cast<double>(i) / static_cast<double>(count);
    const double lo = to - static_cast<double>(count - i) * length;  // the rest must still fit
    const double hi = edges.back() + length;
    double best = std::clamp(even, lo, hi);
    auto best_count = crossing(best);
    for (auto it = std::lower_bound(highs.begin(), highs.end(), lo); it != highs.end() && *it <= hi;
         ++it) {
      if (it != highs.begin() && *it == *(it - 1)) continue;
      const auto n = crossing(*it);
      if (n < best_count || (n == best_count && std::fabs(*it - even) < std::fabs(best - even)))
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

size_t interval_of(const std::vector<double>& edges, double v) {
  const auto it = std::upper_bound(edges.begin() + 1, edges.end() - 1, v);
  return static_cast<size_t>(it - (edges.begin() + 1));
}

// The grid of sheets at 1 : scale, with their match captions and the start corner.
void lay_sheets(const std::vector<InstallerPiece>& pieces, double scale, const Layout& layout,
                InstallerPlan& plan) {
  plan.scale = scale;
  std::vector<std::pair<double, double>> across, up;
  for (const InstallerPiece& p : pieces)
    across.emplace_back(p.bounds.x, p.bounds.right()), up.emplace_back(p.bounds.y, p.bounds.top());
  const std::vector<double> xs = sheet_edges(across, layout.width, plan.viewport[0] * scale, scale);
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

// Places every label at 1 : scale; false when some label found no place.
bool place(const std::vector<InstallerPiece>& pieces, double scale, const Layout& layout,
           InstallerPlan& plan) {
  lay_sheets(pieces, scale, layout, plan);
  const double lh = label_height_mm(plan.text_mm) * scale;
  PlacedLabels placed(lh * 4);
  for (const MatchCaption& c : plan.captions) placed.add(c.box);
  for (const Rect& r : plan.start_corner) placed.add(r);
  plan.labels.assign(pieces.size(), {});
  plan.unplaced = 0;
  std::vector<size_t> beside;
  // Inside first: a label in its own piece cannot meet another piece's, only what is reserved.
  for (size_t i = 0; i < pieces.size(); ++i) {
    const InstallerPiece& p = pieces[i];
    InstallerLabel& label = plan.labels[i];
    label.text = p.id;
    label.anchor = {p.bounds.x + p.bounds.w / 2, p.bounds.y + p.bounds.h / 2};
    label.sheet = sheet_holding(plan, label.anchor[0], label.anchor[1]);
    const Rect& window = plan.sheets[label.sheet].window;
    const double lw = label_width_mm(p.id.size(), plan.text_mm) * scale;
    std::vector<const Rect*> parts;
    for (const Rect& r : p.parts) parts.push_back(&r);
    std::sort(parts.begin(), parts.end(),
              [](const Rect* a, const Rect* b) { return a->area() > b->area(); });
    bool done = false;
    for (const Rect* part : parts) {
      for (const bool rotated : {false, true}) {
        const Rect box = centred(part->x + part->w / 2, part->y + part->h / 2, rotated ? lh : lw,
                                 rotated ? lw : lh);
        if (contains(*part, box) && contains(window, box) && !placed.collides(box)) {
          label.box = box, label.rotated = rotated, label.inside = true;
          placed.add(box);
          done = true;
          break;
        }
      }
      if (done) break;
    }
    if (!done) beside.push_back(i);
  }
  // Then beside: the nearest free place on the piece's own sheet, in eight directions.
  for (const size_t i : beside) {
    InstallerLabel& label = plan.labels[i];
    const Rect& window = plan.sheets[label.sheet].window;
    const double lw = label_width_mm(label.text.size(), plan.text_mm) * scale;
    const auto [cx, cy] = label.anchor;
    const Rect& b = pieces[i].bounds;
    bool done = false;
    for (int k = 1; k <= 24 && !done; ++k) {
      const double d = lh * 0.75 * k;
      const double dirs[8][2] = {{0, 1}, {0, -1}, {1, 0},  {-1, 0},
                                 {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
      for (const auto& dir : dirs) {
        // Clear of the piece's own extent, then d further out.
        const double ox = dir[0] * (b.w / 2 + lw / 2 + d), oy = dir[1] * (b.h / 2 + lh / 2 + d);
        const Rect box = centred(cx + ox, cy + oy, lw, lh);
        if (contains(window, box) && !placed.collides(box)) {
          label.box = box, label.rotated = false, label.inside = false;
          placed.add(box);
          done = true;
          break;
        }
      }
    }
    if (!done) {
      label.box = centred(cx, cy, lw, lh), label.inside = false;
      ++plan.unplaced;
    }
  }
  return plan.unplaced == 0;
}

}  // namespace

size_t sheet_holding(const InstallerPlan& plan, double x, double y) {
  return interval_of(plan.row_edges, y) * plan.grid_columns + interval_of(plan.column_edges, x);
}

std::string match_caption_text(const MatchCaption& caption) {
  return fmt::format("match line: sheet {}", installer_sheet_number(caption.other));
}

double label_width_mm(size_t characters, double text_mm) {
  return (0.96 * static_cast<double>(characters) + 0.8) * text_mm;
}
double label_height_mm(double text_mm) { return 1.7 * text_mm; }

std::array<double, 2> installer_viewport(const PaperSheet& paper, bool landscape) {
  const auto area = drawing_area(paper, landscape);
  return {area[0] - kRowStripMm, area[1] - kColumnStripMm};
}

std::vector<InstallerPiece> installer_pieces(const Layout& layout) {
  std::vector<InstallerPiece> pieces;
  if (!layout.sheets.empty()) {  // installed as fabrication sheets
    for (const auto& sheet : layout.sheets) pieces.push_back({sheet.id, {sheet.area}, sheet.area});
    return pieces;
  }
  pieces.reserve(layout.elements.size());
  for (const Element& e : layout.elements) {
    stop_point();
    const Rect bounds = laid_bounds(e);
    pieces.push_back(
        {e.id, e.shape.empty() || e.circle || e.outline ? std::vector<Rect>{bounds} : e.shape,
         bounds, e.outline ? &*e.outline : nullptr});
  }
  return pieces;
}

// Whether the set is coursed: named so, or left automatic where elements laid in courses are
// small units (a typical piece at most kSmallUnitMm long).
bool coursed_set(const Layout& layout, double typical_w, double typical_h) {
  if (!layout.sheets.empty() || !layout.kind->laid_in_courses() || layout.elements.empty())
    return false;
  switch (layout.drawing.installer_set) {
    case InstallerSet::coursed:
      return true;
    case InstallerSet::labelled:
      return false;
    case InstallerSet::automatic:
      break;
  }
  return std::max(typical_w, typical_h) <= kSmallUnitMm;
}

InstallerPlan plan_installer_sheets(const Layout& layout) {
  InstallerPlan plan;
  const DrawingKeys& keys = layout.drawing;
  plan.paper = paper_sheet(keys.installer_paper.empty() ? keys.paper : keys.installer_paper)
                   .value_or(*paper_sheet("A3"));
  plan.landscape = layout.width >= layout.height;
  plan.viewport = installer_viewport(plan.paper, plan.landscape);
  plan.pieces = installer_pieces(layout);
  const std::vector<InstallerPiece>& pieces = plan.pieces;
  // The typical piece: the median by area. Its label must fit inside it, across or along.
  double typical_w = layout.width, typical_h = layout.height;
  size_t longest = 1;
  if (!pieces.empty()) {
    std::vector<const InstallerPiece*> order;
    for (const InstallerPiece& p : pieces) {
      order.push_back(&p);
      longest = std::max(longest, p.id.size());
    }
    std::nth_element(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(order.size() / 2),
                     order.end(), [](const InstallerPiece* a, const InstallerPiece* b) {
                       return a->bounds.area() < b->bounds.area();
                     });
    typical_w = order[order.size() / 2]->bounds.w;
    typical_h = order[order.size() / 2]->bounds.h;
  }
  if (coursed_set(layout, typical_w, typical_h)) {
    // Landscape, whatever the wall's shape: a portrait sheet's title strip leaves no room for
    // the key and the courses a sheet holds beside the title block.
    plan.coursed = true;
    plan.landscape = true;
    plan.viewport = installer_viewport(plan.paper, true);
    lay_sheets(pieces, keys.installer_scale > 0 ? keys.installer_scale : kCoursedScale, layout,
               plan);
    return plan;
  }
  // The largest text at which the typical piece holds the longest label at 1 : n.
  auto text_that_fits = [&](double n) {
    const double w = typical_w / n, h = typical_h / n;
    const double per_text = label_width_mm(longest, 1), tall = label_height_mm(1);
    return std::max(std::min(w / per_text, h / tall), std::min(h / per_text, w / tall));
  };
  if (keys.installer_scale > 0) {  // named: labels that find no room are counted on the sheet
    plan.text_mm =
        std::clamp(text_that_fits(keys.installer_scale), kInstallerMinTextMm, kInstallerTextMm);
    place(pieces, keys.installer_scale, layout, plan);
    return plan;
  }
  const std::vector<double>& scales = standard_scales();
  // The largest standard scale at which the typical piece holds its label, and no larger than
  // the one the whole layout is drawn at on sheet 1.
  const double whole = fit_to_sheet(layout.width, layout.height, plan.paper).scale;
  std::ptrdiff_t start = 0;
  for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t>(scales.size()); ++i) {
    const double n = scales[static_cast<size_t>(i)];
    if (n > whole) break;
    if (text_that_fits(n) >= kInstallerMinTextMm) start = i;
  }
  for (std::ptrdiff_t i = start, tried = 0;
       i >= 0 && tried < static_cast<std::ptrdiff_t>(kScalesTried); --i, ++tried) {
    const double n = scales[static_cast<size_t>(i)];
    plan.text_mm = std::clamp(text_that_fits(n), kInstallerMinTextMm, kInstallerTextMm);
    if (place(pieces, n, layout, plan)) break;
  }
  return plan;
}

}  // namespace curdle
