#include "layout/installer_sheets.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "curdle/stop.h"
#include "layout/installer_sheet_grid.h"
#include "layout/piece.h"
#include "layout/zone.h"

namespace curdle {
namespace {

constexpr double kRowStripMm = 14;    // row numbers, left of the frame
constexpr double kColumnStripMm = 8;  // column numbers, under the frame
// A coursed sheet's setting-out marks: the gauge rod right of the frame, the chain of
// dimensions under the column numbers (gauge.h).
constexpr double kGaugeStripMm = 24, kDimensionStripMm = 10;
constexpr size_t kScalesTried = 6;  // smaller scales tried when labels do not all find room

bool contains(const Rect& outer, const Rect& inner) {
  const double e = 1e-6;
  return inner.x >= outer.x - e && inner.y >= outer.y - e && inner.right() <= outer.right() + e &&
         inner.top() <= outer.top() + e;
}

struct Point {
  double x = 0, y = 0;
};

// Which side of the line a -> b the point c lies on (0: on it).
int side(Point a, Point b, Point c) {
  const double cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const double scale = std::max({std::fabs(b.x - a.x), std::fabs(b.y - a.y), 1.0});
  return cross > 1e-9 * scale ? 1 : cross < -1e-9 * scale ? -1 : 0;
}

bool on_segment(Point a, Point b, Point c) {
  return std::min(a.x, b.x) - 1e-9 <= c.x && c.x <= std::max(a.x, b.x) + 1e-9 &&
         std::min(a.y, b.y) - 1e-9 <= c.y && c.y <= std::max(a.y, b.y) + 1e-9;
}

// Two leaders meet: they cross, or one ends on the other.
bool segments_meet(Point a, Point b, Point c, Point d) {
  const int d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && on_segment(c, d, a)) || (d2 == 0 && on_segment(c, d, b)) ||
         (d3 == 0 && on_segment(a, b, c)) || (d4 == 0 && on_segment(a, b, d));
}

// The segment a -> b clipped to [left, right] x [low, high], Liang-Barsky, leaves more than a
// point.
[[gnu::noinline]] bool clipped_enters(Point a, Point b, double left, double right, double low,
                                      double high) {
  double t0 = 0, t1 = 1;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - left, right - a.x, a.y - low, high - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 >= t1) return false;
  }
  return true;
}

// A leader runs through a box's inside (touching its edge is not crossing it): the segment
// clipped to the box shrunk by a rounding error leaves more than a point. One wholly to one
// side of the shrunk box is not clipped at all (the clipping's quotients round the same way,
// to nothing): most leaders a label is tried against.
inline bool segment_enters(Point a, Point b, const Rect& r) {
  const double e = 1e-6;
  const double left = r.x + e, right = r.right() - e, low = r.y + e, high = r.top() - e;
  if (std::max(a.x, b.x) < left || std::min(a.x, b.x) > right || std::max(a.y, b.y) < low ||
      std::min(a.y, b.y) > high)
    return false;
  return clipped_enters(a, b, left, right, low, high);
}

// How much a label beside its piece may give way when the sheet is crowded: not at all; its
// leader over labels inside their pieces; or only its box kept off every other label.
enum class Leeway { none, over_inside, box_only };

// What is already on the sheets: labels inside and beside their pieces, captions, leaders and
// the dots they start from, each with the piece it belongs to, found by a grid of buckets over
// `extent`. A flat grid: a hash map of buckets spent half the labels' time finding its keys.
// Whatever lies outside the extent shares the border's buckets, where a query there finds it.
class PlacedLabels {
 public:
  enum class Mark { reserved, inside, beside, dot, leader };
  static constexpr size_t kNobody = static_cast<size_t>(-1);
  PlacedLabels(double bucket, const Rect& extent) : x0_(extent.x), y0_(extent.y) {
    constexpr double kMostBucketsASide = 1024;  // a larger bucket beyond, for the grid's memory
    bucket_ = std::max({bucket, extent.w / kMostBucketsASide, extent.h / kMostBucketsASide});
    if (!(bucket_ > 0) || !std::isfinite(bucket_)) bucket_ = 1;
    nx_ = along(extent.right(), x0_, static_cast<int64_t>(kMostBucketsASide)) + 1;
    ny_ = along(extent.top(), y0_, static_cast<int64_t>(kMostBucketsASide)) + 1;
    buckets_.resize(static_cast<size_t>(nx_ * ny_));
  }

  // A box is free when it overlaps no other piece's box and no leader runs through it.
  bool box_free(const Rect& r, size_t owner = kNobody, Leeway leeway = Leeway::none) const {
    return none_near(r, [&](const Item& item) {
      if (item.owner == owner && owner != kNobody) return false;
      if (item.mark == Mark::leader)
        return leeway != Leeway::box_only && segment_enters(item.from, item.to, r);
      if (item.mark == Mark::dot && leeway == Leeway::box_only) return false;
      return overlaps(item.box, r);
    });
  }
  // A leader is free when it runs through no other piece's box and meets no other leader.
  bool leader_free(Point a, Point b, size_t owner, Leeway leeway = Leeway::none) const {
    if (leeway == Leeway::box_only) return true;
    return none_near(spanning(a, b), [&](const Item& item) {
      if (item.owner == owner && owner != kNobody) return false;
      if (item.mark == Mark::inside && leeway == Leeway::over_inside) return false;
      return item.mark == Mark::leader ? segments_meet(a, b, item.from, item.to)
                                       : segment_enters(a, b, item.box);
    });
  }
  void add(const Rect& r, Mark mark, size_t owner = kNobody) {
    store(r, Item{r, {}, {}, owner, mark});
  }
  void add_leader(Point a, Point b, size_t owner) {
    store(spanning(a, b), Item{{}, a, b, owner, Mark::leader});
  }

 private:
  struct Item {
    Rect box;
    Point from, to;
    size_t owner;
    Mark mark;
    int32_t first_x = 0, first_y = 0;  // the first bucket of those it is kept in
  };
  struct Buckets {
    int64_t lo_x, hi_x, lo_y, hi_y;
  };
  static Rect spanning(Point a, Point b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::fabs(b.x - a.x), std::fabs(b.y - a.y)};
  }
  // The bucket along one axis holding v, within [0, last].
  int64_t along(double v, double origin, int64_t last) const {
    const double k = std::floor((v - origin) / bucket_);
    if (!(k > 0)) return 0;
    return k >= static_cast<double>(last) ? last : static_cast<int64_t>(k);
  }
  Buckets covering(const Rect& r) const {
    return {along(r.x, x0_, nx_ - 1), along(r.right(), x0_, nx_ - 1), along(r.y, y0_, ny_ - 1),
            along(r.top(), y0_, ny_ - 1)};
  }
  void store(const Rect& r, Item item) {
    const Buckets b = covering(r);
    item.first_x = static_cast<int32_t>(b.lo_x), item.first_y = static_cast<int32_t>(b.lo_y);
    for (int64_t y = b.lo_y; y <= b.hi_y; ++y)
      for (int64_t x = b.lo_x; x <= b.hi_x; ++x)
        buckets_[static_cast<size_t>(y * nx_ + x)].push_back(item);
  }
  // Whether any item near r hits; each item is asked once, in the first bucket it shares with
  // r (a piece's box spans several buckets, and a query several more).
  template <class Hits>
  bool none_near(const Rect& r, Hits&& hits) const {
    const Buckets b = covering(r);
    for (int64_t y = b.lo_y; y <= b.hi_y; ++y)
      for (int64_t x = b.lo_x; x <= b.hi_x; ++x)
        for (const Item& item : buckets_[static_cast<size_t>(y * nx_ + x)]) {
          if (std::max<int64_t>(item.first_x, b.lo_x) != x ||
              std::max<int64_t>(item.first_y, b.lo_y) != y)
            continue;
          if (hits(item)) return false;
        }
    return true;
  }
  double x0_, y0_, bucket_ = 1;
  int64_t nx_ = 1, ny_ = 1;
  std::vector<std::vector<Item>> buckets_;
};

// Where a leader from the piece's centre meets its label: the box's nearest point.
Point leader_end(const std::array<double, 2>& anchor, const Rect& box) {
  return {std::clamp(anchor[0], box.x, box.right()), std::clamp(anchor[1], box.y, box.top())};
}

// A point inside an outline's rings (even-odd: its islands are out).
bool within_rings(const std::vector<Ring>& rings, double x, double y) {
  bool in = false;
  for (const Ring& ring : rings) in = in != curdle::contains(ring, x, y);
  return in;
}

// A label's box on a piece cut along a sloping or curved edge: its corners inside the cut
// outline and no corner of the outline inside it.
bool within_outline(const Outline& outline, const Rect& box) {
  for (const double x : {box.x, box.right()})
    for (const double y : {box.y, box.top()})
      if (!within_rings(outline.rings, x, y)) return false;
  for (const Ring& ring : outline.rings)
    for (const auto& p : ring)
      if (p[0] > box.x && p[0] < box.right() && p[1] > box.y && p[1] < box.top()) return false;
  return true;
}

// A place for the label inside its piece on the piece's own sheet: in the middle of its largest
// part that holds it, across or along, else moved towards the part's sides; false when none.
bool place_inside(const InstallerPiece& piece, double lh, double scale, const InstallerPlan& plan,
                  PlacedLabels& placed, size_t owner, InstallerLabel& label, size_t split) {
  const Rect& window = plan.sheets[label.sheet].window;
  const size_t longest = split ? std::max(split, piece.id.size() - split - 1) : piece.id.size();
  const double lw = label_width_mm(longest, plan.text_mm) * scale;
  const double tall = split ? 2 * lh : lh;
  std::vector<const Rect*> parts;
  for (const Rect& r : piece.parts) parts.push_back(&r);
  std::sort(parts.begin(), parts.end(),
            [](const Rect* a, const Rect* b) { return a->area() > b->area(); });
  // Offsets from the middle, in units of the room left each way.
  const double shifts[9][2] = {{0, 0}, {0, 1},  {0, -1}, {1, 0},  {-1, 0},
                               {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
  for (const Rect* part : parts)
    for (const auto& shift : shifts)
      for (const bool rotated : {false, true}) {
        const double w = rotated ? tall : lw, h = rotated ? lw : tall;
        const double room_x = (part->w - w) / 2, room_y = (part->h - h) / 2;
        if (room_x < 0 || room_y < 0) continue;
        const Rect box = centred_on(part->x + part->w / 2 + shift[0] * room_x,
                                    part->y + part->h / 2 + shift[1] * room_y, w, h);
        if (contains(window, box) && placed.box_free(box, owner) &&
            (!piece.outline || within_outline(*piece.outline, box))) {
          label.box = box, label.rotated = rotated, label.inside = true, label.split = split;
          placed.add(box, PlacedLabels::Mark::inside, owner);
          return true;
        }
      }
  return false;
}

// Inside, in one line or else in two (the ID broken at its last '-'): a piece that holds its ID
// only in two lines (a brick split by a match line, say) keeps it inside, off everyone's way.
bool place_inside_in_lines(const InstallerPiece& piece, double lh, double scale,
                           const InstallerPlan& plan, PlacedLabels& placed, size_t owner,
                           InstallerLabel& label) {
  if (place_inside(piece, lh, scale, plan, placed, owner, label, 0)) return true;
  const size_t at = piece.id.rfind('-');
  if (at == std::string::npos || at == 0 || at + 1 >= piece.id.size()) return false;
  return place_inside(piece, lh, scale, plan, placed, owner, label, at);
}

// The nearest free place beside a piece on its own sheet, in eight directions (across or,
// left and right, along the edge), whose leader crosses no other label or leader; false when
// there is none. `avoid`: boxes the label must also keep off.
bool place_beside(const InstallerPiece& piece, double lh, double scale, const InstallerPlan& plan,
                  PlacedLabels& placed, const PlacedLabels* avoid, Leeway leeway, size_t owner,
                  InstallerLabel& label) {
  const Rect& window = plan.sheets[label.sheet].window;
  const double lw = label_width_mm(label.text.size(), plan.text_mm) * scale;
  const auto [cx, cy] = label.anchor;
  const Rect& b = piece.bounds;
  const double dirs[8][2] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
  for (int k = 1; k <= 24; ++k) {
    const double d = lh * 0.75 * k;
    for (const auto& dir : dirs)
      for (const bool rotated : {false, true}) {
        if (rotated && dir[1] != 0) continue;  // reading up the edge it stands beside
        const double w = rotated ? lh : lw, h = rotated ? lw : lh;
        // Clear of the piece's own extent, then d further out; slid along the sheet's edge
        // where it would leave the sheet, but never back onto the piece.
        Rect box = centred_on(cx + dir[0] * (b.w / 2 + w / 2 + d),
                              cy + dir[1] * (b.h / 2 + h / 2 + d), w, h);
        box.x = std::clamp(box.x, window.x, std::max(window.x, window.right() - w));
        box.y = std::clamp(box.y, window.y, std::max(window.y, window.top() - h));
        if (overlaps(box, b)) continue;
        if (!contains(window, box) || !placed.box_free(box, owner, leeway)) continue;
        if (avoid && !avoid->box_free(box)) continue;
        const Point end = leader_end(label.anchor, box);
        if (!placed.leader_free({cx, cy}, end, owner, leeway)) continue;
        label.box = box, label.rotated = rotated, label.inside = false;
        placed.add(box, PlacedLabels::Mark::beside, owner);
        placed.add_leader({cx, cy}, end, owner);
        return true;
      }
  }
  return false;
}

// Where labels are placed: the sheets' windows and the pieces.
Rect placing_extent(const std::vector<InstallerPiece>& pieces, const InstallerPlan& plan) {
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  auto take = [&](const Rect& r) {
    x0 = std::min(x0, r.x), y0 = std::min(y0, r.y);
    x1 = std::max(x1, r.right()), y1 = std::max(y1, r.top());
  };
  for (const InstallerPiece& p : pieces) take(p.bounds);
  for (const auto& sheet : plan.sheets) take(sheet.window);
  if (!(x0 <= x1 && y0 <= y1)) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

// Places every label at 1 : scale; false when some label found no place.
bool place(const std::vector<InstallerPiece>& pieces, double scale, const Layout& layout,
           InstallerPlan& plan) {
  lay_sheets(pieces, scale, layout, plan);
  const double lh = label_height_mm(plan.text_mm) * scale;
  const double dot = 2 * kLeaderDotMm * scale;
  const Rect extent = placing_extent(pieces, plan);
  auto reserved = [&] {
    PlacedLabels placed(lh * 3, extent);
    for (const MatchCaption& c : plan.captions) placed.add(c.box, PlacedLabels::Mark::reserved);
    for (const Rect& r : plan.start_corner) placed.add(r, PlacedLabels::Mark::reserved);
    return placed;
  };
  plan.labels.assign(pieces.size(), {});
  plan.unplaced = 0, plan.over_labels = 0;
  // Inside first, off every other piece (a ground cell's label off the tree or bench standing
  // on it, whose leader may have to start at its centre).
  PlacedLabels placed = reserved();
  for (size_t i = 0; i < pieces.size(); ++i) {
    InstallerLabel& label = plan.labels[i];
    label.text = pieces[i].id;
    label.anchor = {pieces[i].bounds.x + pieces[i].bounds.w / 2,
                    pieces[i].bounds.y + pieces[i].bounds.h / 2};
    label.sheet = sheet_holding(plan, label.anchor[0], label.anchor[1]);
    placed.add(pieces[i].bounds, PlacedLabels::Mark::reserved, i);
  }
  std::vector<size_t> beside;
  for (size_t i = 0; i < pieces.size(); ++i)
    if (!place_inside_in_lines(pieces[i], lh, scale, plan, placed, i, plan.labels[i]))
      beside.push_back(i);
  // Then beside, among the labels inside and the dots of the leaders to come: at first off the
  // other pieces that need room beside them too, so that no label walls another in; then
  // wherever there is room.
  placed = reserved();
  PlacedLabels needing_room(lh * 3, extent);
  for (size_t i = 0; i < pieces.size(); ++i)
    if (plan.labels[i].inside) placed.add(plan.labels[i].box, PlacedLabels::Mark::inside, i);
  for (const size_t i : beside) {
    const auto [cx, cy] = plan.labels[i].anchor;
    placed.add(centred_on(cx, cy, dot, dot), PlacedLabels::Mark::dot, i);
    needing_room.add(pieces[i].bounds, PlacedLabels::Mark::reserved, i);
  }
  // Walled in (a piece split by a match line in a bond whose every unit holds its ID, say), a
  // leader runs over labels inside their pieces; failing that, as the last resort, anywhere
  // its label's box is clear of the others. Those leaders are counted.
  std::vector<size_t> left = beside;
  struct Pass {
    const PlacedLabels* avoid;
    Leeway leeway;
  };
  const Pass passes[] = {{&needing_room, Leeway::none},
                         {nullptr, Leeway::none},
                         {nullptr, Leeway::over_inside},
                         {nullptr, Leeway::box_only}};
  for (const Pass& pass : passes) {
    std::vector<size_t> still;
    for (const size_t i : left)
      if (!place_beside(pieces[i], lh, scale, plan, placed, pass.avoid, pass.leeway, i,
                        plan.labels[i]))
        still.push_back(i);
      else if (pass.leeway != Leeway::none)
        plan.labels[i].crowded = true, ++plan.over_labels;
    left = std::move(still);
  }
  for (const size_t i : left) {
    InstallerLabel& label = plan.labels[i];
    const double lw = label_width_mm(label.text.size(), plan.text_mm) * scale;
    label.box = centred_on(label.anchor[0], label.anchor[1], lw, lh), label.inside = false;
    ++plan.unplaced;
  }
  return plan.unplaced == 0;
}

}  // namespace

std::vector<std::string> label_lines(const InstallerLabel& label) {
  if (!label.split) return {label.text};
  return {label.text.substr(0, label.split), label.text.substr(label.split + 1)};
}

std::array<double, 2> leader_end(const InstallerLabel& label) {
  const Point end = leader_end(label.anchor, label.box);
  return {end.x, end.y};
}

std::string match_caption_text(const MatchCaption& caption) {
  return fmt::format("match line: sheet {}", installer_sheet_number(caption.other));
}

double label_width_mm(size_t characters, double text_mm) {
  return (0.96 * static_cast<double>(characters) + 0.8) * text_mm;
}
double label_height_mm(double text_mm) { return 1.7 * text_mm; }

std::array<double, 2> installer_viewport(const PaperSheet& paper, bool landscape, bool coursed) {
  const auto area = drawing_area(paper, landscape);
  if (coursed)
    return {area[0] - kRowStripMm - kGaugeStripMm, area[1] - kColumnStripMm - kDimensionStripMm};
  return {area[0] - kRowStripMm, area[1] - kColumnStripMm};
}

std::vector<InstallerPiece> installer_pieces(const Layout& layout) {
  std::vector<InstallerPiece> pieces;
  if (layout.fabrication) {  // installed as fabrication sheets
    for (const auto& sheet : layout.sheets())
      pieces.push_back({sheet.id, {sheet.area}, sheet.area});
    return pieces;
  }
  pieces.reserve(layout.elements.size());
  for (const Element& e : layout.elements) {
    stop_point();
    const Rect bounds = label_bounds(e);
    pieces.push_back(
        {e.id, e.shape.empty() || e.circle || e.outline ? std::vector<Rect>{bounds} : e.shape,
         bounds, e.outline ? &*e.outline : nullptr});
  }
  return pieces;
}

// Whether the set is coursed: named so, or left automatic where elements laid in courses are
// small units (a typical piece at most kSmallUnitMm long).
bool coursed_set(const Layout& layout, double typical_w, double typical_h) {
  if (layout.fabrication || !layout.kind->laid_in_courses() || layout.elements.empty())
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
    plan.viewport = installer_viewport(plan.paper, true, true);
    if (keys.installer_scale > 0) check_named_scale(layout, plan, keys.installer_scale);
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
    check_named_scale(layout, plan, keys.installer_scale);
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
  // Down from there until every label has a place, and on while the set stays within twice
  // as many sheets, for the plan whose leaders run over the fewest labels.
  std::optional<InstallerPlan> best;
  size_t most_sheets = 0;
  for (std::ptrdiff_t i = start, tried = 0;
       i >= 0 && tried < static_cast<std::ptrdiff_t>(kScalesTried); --i, ++tried) {
    const double n = scales[static_cast<size_t>(i)];
    plan.text_mm = std::clamp(text_that_fits(n), kInstallerMinTextMm, kInstallerTextMm);
    const bool placed = place(pieces, n, layout, plan);
    if (best && plan.sheets.size() > most_sheets) break;
    if (placed && !best) most_sheets = 2 * plan.sheets.size();
    if (placed && (!best || plan.over_labels < best->over_labels)) best = plan;
    if (placed && plan.over_labels == 0) break;
  }
  if (best) plan = std::move(*best);
  return plan;
}

}  // namespace curdle
