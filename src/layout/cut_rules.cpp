#include "layout/cut_rules.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

#include "curdle/stop.h"
#include "layout/builder.h"
#include "layout/piece.h"

namespace curdle {
namespace {

constexpr double kEps = 1e-6;

using Span = std::pair<double, double>;

// Spans sorted and joined where they touch.
std::vector<Span> joined(std::vector<Span> spans) {
  std::sort(spans.begin(), spans.end());
  std::vector<Span> out;
  for (const Span& s : spans) {
    if (!out.empty() && s.first <= out.back().second + kEps)
      out.back().second = std::max(out.back().second, s.second);
    else
      out.push_back(s);
  }
  return out;
}

// The cut pieces narrower than `least` where material [a, b] along an axis meets a grid of
// `module` + joint = `pitch`, moved back by `shift` from the anchor at 0.
uint64_t slivers_in(double a, double b, double module, double pitch, double shift, double least) {
  uint64_t count = 0;
  const double k0 = std::floor((a + shift) / pitch), k1 = std::floor((b - kEps + shift) / pitch);
  for (const double k : {k0, k1}) {
    const double start = k * pitch - shift;
    const double piece = std::min(b, start + module) - std::max(a, start);
    if (piece > kEps && piece < module - kEps && piece < least - kEps) ++count;
    if (k1 == k0) break;
  }
  return count;
}

// The cut pieces of any width there: what a shift trades its slivers against.
uint64_t cuts_in(double a, double b, double module, double pitch, double shift) {
  return slivers_in(a, b, module, pitch, shift, module);
}

}  // namespace

double narrowest_run(const std::vector<Rect>& pieces, bool along_x) {
  std::vector<double> bands;
  for (const Rect& r : pieces) {
    bands.push_back(along_x ? r.y : r.x);
    bands.push_back(along_x ? r.top() : r.right());
  }
  std::sort(bands.begin(), bands.end());
  double least = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < bands.size(); ++i) {
    if (bands[i + 1] - bands[i] < kEps) continue;
    const double mid = (bands[i] + bands[i + 1]) / 2;
    std::vector<Span> runs;
    for (const Rect& r : pieces) {
      const double lo = along_x ? r.y : r.x, hi = along_x ? r.top() : r.right();
      if (lo < mid && mid < hi) runs.push_back(along_x ? Span{r.x, r.right()} : Span{r.y, r.top()});
    }
    for (const Span& s : joined(std::move(runs))) least = std::min(least, s.second - s.first);
  }
  return std::isfinite(least) ? least : 0.0;
}

double least_cut(const LayoutSpec& spec, int axis) {
  const double given = spec.min_cut[static_cast<size_t>(axis)];
  if (given > 0) return given;
  return (axis == 0 ? spec.module_w : spec.module_h) / 3;
}

ShiftAdvice best_shift(const Layout& layout, const LayoutSpec& spec, int axis) {
  const int other = 1 - axis;
  const double extent = axis == 0 ? layout.width : layout.height;
  const double across = other == 0 ? layout.width : layout.height;
  const double module = axis == 0 ? spec.module_w : spec.module_h;
  const double other_module = other == 0 ? spec.module_w : spec.module_h;
  const double pitch = module + spec.joint, other_pitch = other_module + spec.joint;
  const bool high = axis == 0 ? from_right(spec.origin) : from_top(spec.origin);
  const bool other_high = other == 0 ? from_right(spec.origin) : from_top(spec.origin);
  const int64_t lines = other == 0 ? layout.columns : layout.rows;
  auto lo = [](const Rect& r, int a) { return a == 0 ? r.x : r.y; };
  auto hi = [](const Rect& r, int a) { return a == 0 ? r.right() : r.top(); };

  // Bands across the surface between openings' edges; in each, the material is the surface
  // less the openings that span the band, and every row (or column) in it meets the same cuts.
  std::vector<double> edges{0, across};
  const std::vector<Rect> holes = layout.holes();
  for (const Rect& o : holes) edges.push_back(lo(o, other)), edges.push_back(hi(o, other));
  std::sort(edges.begin(), edges.end());
  struct Band {
    uint64_t lines = 0;
    std::vector<Span> material;  // from the anchor of the axis
  };
  std::vector<Band> bands;
  for (size_t i = 0; i + 1 < edges.size(); ++i) {
    const double b0 = edges[i], b1 = edges[i + 1], mid = (b0 + b1) / 2;
    if (b1 - b0 < kEps) continue;
    Band band;
    for (int64_t k = 0; k < lines; ++k) {  // rows (or columns) that reach into the band
      const double start = k * other_pitch - spec.shift[other];
      const double s0 = other_high ? across - start - other_module : start;
      if (std::min(b1, s0 + other_module) - std::max(b0, s0) > kEps) ++band.lines;
    }
    std::vector<Span> spans;
    for (const Rect& o : holes)
      if (lo(o, other) < mid && mid < hi(o, other)) spans.push_back({lo(o, axis), hi(o, axis)});
    double at = 0;
    for (const Span& h : joined(std::move(spans))) {
      if (h.first > at + kEps) band.material.push_back({at, h.first});
      at = std::max(at, h.second);
    }
    if (extent > at + kEps) band.material.push_back({at, extent});
    if (high)
      for (Span& s : band.material) s = {extent - s.second, extent - s.first};
    if (band.lines) bands.push_back(std::move(band));
  }
  const double least = least_cut(spec, axis);
  // Per shift: the slivers, then the cut pieces of any width (a shift that clears the slivers
  // by cutting a whole course more is worse than one that clears them with fewer cuts).
  auto count = [&](double shift) {
    std::pair<uint64_t, uint64_t> n{0, 0};
    for (const Band& band : bands)
      for (const Span& s : band.material) {
        n.first += band.lines * slivers_in(s.first, s.second, module, pitch, shift, least);
        n.second += band.lines * cuts_in(s.first, s.second, module, pitch, shift);
      }
    return n;
  };
  ShiftAdvice advice;
  advice.shift = spec.shift[axis];
  std::tie(advice.slivers, advice.cuts) = count(spec.shift[axis]);
  advice.now = advice.slivers;
  advice.cuts_now = advice.cuts;
  if (advice.slivers == 0) return advice;
  // Whole millimetres (coarser for elements over 4 m): what a setter-out can mark.
  const double step = std::max(1.0, std::ceil(module / 4000));
  for (double s = 0; s < module - kEps; s += step) {
    const auto n = count(s);
    if (n < std::pair{advice.slivers, advice.cuts})
      std::tie(advice.slivers, advice.cuts) = n, advice.shift = s;
  }
  return advice;
}

namespace {

// A cut piece narrower than the rule across one axis.
struct Sliver {
  size_t element = 0;
  int axis = 0;
  double run = 0;     // its narrowest run across that axis, mm
  const char* where;  // what cut it
};

// A pattern's cut unit narrower than the rule across one of its own sides: measured along the
// unit's length and across its width (a hexagon: across each pair of flats), as the axis the
// rule names (0: along the unit's length, 1: across it) and the run.
std::optional<std::pair<int, double>> pattern_sliver(const Layout& layout, const LayoutSpec& spec,
                                                     const Element& e) {
  const bool hexagon =
      layout.pattern == LayingPattern::hexagon || layout.pattern == LayingPattern::hexagon_flat;
  const double pi = 3.14159265358979323846;
  std::vector<std::pair<int, double>> directions;  // (rule axis, degrees)
  if (hexagon)
    directions = {{0, e.turn}, {0, e.turn + 60}, {0, e.turn + 120}};
  else
    directions = {{0, e.turn}, {1, e.turn + 90}};
  for (const auto& [axis, degrees] : directions) {
    const double c = std::cos(degrees * pi / 180), s = std::sin(degrees * pi / 180);
    double lo = 1e300, hi = -1e300;
    for (const Ring& ring : e.outline->rings)
      for (const auto& [x, y] : ring)
        lo = std::min(lo, x * c + y * s), hi = std::max(hi, x * c + y * s);
    if (hi - lo < least_cut(spec, axis) - kEps) return std::pair{axis, hi - lo};
  }
  return std::nullopt;
}

std::vector<Sliver> find_slivers(const Layout& layout, const LayoutSpec& spec) {
  std::vector<Sliver> out;
  for (size_t i = 0; i < layout.elements.size(); ++i) {
    stop_point();
    const Element& e = layout.elements[i];
    if (!e.cut) continue;
    const Rect laid = clip(e.nominal, layout.width, layout.height);
    if (layout.pattern != LayingPattern::grid) {  // across the unit's own sides
      if (const auto s = pattern_sliver(layout, spec, e))
        out.push_back({i, s->first, s->second, "an edge or opening"});
      continue;
    }
    for (int axis = 0; axis < 2; ++axis) {
      // A piece cut along a sloping edge: its extent along each axis.
      const double run =
          narrowest_run(e.outline ? std::vector<Rect>{laid_bounds(e)} : e.shape, axis == 0);
      if (run >= least_cut(spec, axis) - kEps) continue;
      const double laid_extent = axis == 0 ? laid.w : laid.h;
      const double module = axis == 0 ? spec.module_w : spec.module_h;
      const bool at_edge = laid_extent < module - kEps && std::fabs(laid_extent - run) < kEps;
      out.push_back({i, axis, run,
                     e.outline ? "a sloping or curved edge"
                     : at_edge ? "the edge"
                               : "an opening"});
      break;
    }
  }
  return out;
}

// "12 of 27.5 x 65 mm, 4 of 215 x 15 mm": the slivers' pieces by their laid size (to the half
// millimetre), most first; a piece that is not one rectangle (an L round a window's corner, a
// piece cut along a slope) is "shaped" within that size.
std::string specials(const Layout& layout, const std::vector<Sliver>& slivers) {
  std::map<std::string, uint64_t> sizes;
  for (const Sliver& s : slivers) {
    const Element& e = layout.elements[s.element];
    const Rect r = laid_bounds(e);
    ++sizes[fmt::format("{:g} x {:g} mm{}", std::round(r.w * 2) / 2, std::round(r.h * 2) / 2,
                        e.outline || e.shape.size() > 1 ? " shaped" : "")];
  }
  std::vector<std::pair<uint64_t, std::string>> most;
  for (const auto& [size, n] : sizes) most.push_back({n, size});
  std::stable_sort(most.begin(), most.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string out;
  for (size_t i = 0; i < most.size() && i < 6; ++i)
    out += fmt::format("{}{} of {}", i ? ", " : "", most[i].first, most[i].second);
  if (most.size() > 6) out += fmt::format(" and {} other sizes", most.size() - 6);
  return out;
}

const char* rule_name(const LayoutSpec& spec) {
  return spec.min_cut[0] > 0 || spec.min_cut[1] > 0 ? "layout.min_cut" : "a third of the element";
}

}  // namespace

void check_cut_widths(Layout& layout, const LayoutSpec& spec, const std::vector<Rect>& openings) {
  const std::vector<Sliver> slivers = find_slivers(layout, spec);
  if (slivers.empty()) return;
  for (const Sliver& s : slivers)
    layout.violations.push_back(fmt::format(
        "{}: cut to {:.1f} mm {} at {}, below {:.1f} mm ({})", layout.elements[s.element].id, s.run,
        layout.pattern != LayingPattern::grid ? (s.axis == 0 ? "long" : "wide")
        : s.axis == 0                         ? "wide"
                                              : "high",
        s.where, least_cut(spec, s.axis), rule_name(spec)));
  std::string note =
      fmt::format("{} cut {}{} narrower than {} (see the rule violations)", slivers.size(),
                  layout.element_type, slivers.size() == 1 ? " is" : "s are", rule_name(spec));
  if (spec.centred || !spec.size || spec.pattern != LayingPattern::grid) {
    note += fmt::format("; lay specials or closers: {}", specials(layout, slivers));
    return layout.notes.push_back(note);
  }
  // The counts along rows and columns find each axis's best shift; laying the surface with them
  // (both, or one) checks what they leave, and only a shift that leaves fewer is advised.
  const ShiftAdvice x = best_shift(layout, spec, 0), y = best_shift(layout, spec, 1);
  // Trials are ranked by the slivers they leave, then by the pieces they cut: the rules first,
  // then as few cuts as the rules allow.
  struct Trial {
    LayoutSpec spec;
    Layout blank;
    std::vector<Sliver> left;
    size_t cut = 0;
  };
  auto cut_pieces = [](const Layout& l) {
    size_t n = 0;
    for (const Element& e : l.elements) n += e.cut ? 1 : 0;
    return n;
  };
  const size_t cut_now = cut_pieces(layout);
  // Each shift once: where one axis keeps its shift, two of the three are the same.
  std::vector<std::array<double, 2>> shifts;
  for (const std::array<double, 2> shift :
       {std::array{x.shift, y.shift}, std::array{x.shift, spec.shift[1]},
        std::array{spec.shift[0], y.shift}})
    if (shift != spec.shift && std::find(shifts.begin(), shifts.end(), shift) == shifts.end())
      shifts.push_back(shift);
  std::optional<Trial> best;
  std::pair<size_t, size_t> fewest{slivers.size(), cut_now};
  for (const std::array<double, 2>& shift : shifts) {
    LayoutSpec trial = spec;
    trial.shift = shift;
    Layout blank = lay_blank_grid(trial, openings);
    std::vector<Sliver> left = find_slivers(blank, trial);
    const std::pair<size_t, size_t> leaves{left.size(), cut_pieces(blank)};
    if (leaves < fewest) {
      fewest = leaves;
      best.emplace(Trial{std::move(trial), std::move(blank), std::move(left), leaves.second});
    }
  }
  if (!best) {
    note += fmt::format("; no shift of the grid leaves fewer: lay specials or closers, {}",
                        specials(layout, slivers));
    return layout.notes.push_back(note);
  }
  const auto cells = elements_to_cover(best->spec);
  note += fmt::format(
      "; layout.shift = [{:g}, {:g}] leaves {} (checked by laying it; the window then takes {} x "
      "{} cells) and cuts {} {}s, against {} now{}",
      best->spec.shift[0] + 0.0, best->spec.shift[1] + 0.0,
      fewest.first ? std::to_string(fewest.first) : "none", cells[0], cells[1], best->cut,
      layout.element_type, cut_now,
      best->cut > cut_now ? ": fewer specials for more cut pieces, weigh the two" : "");
  if (fewest.first)
    note += fmt::format("; what it leaves needs specials or closers: {}",
                        specials(best->blank, best->left));
  layout.notes.push_back(note);
}

void report_open_area(Layout& layout, size_t openings) {
  const double wall = layout.width * layout.height;
  if (wall <= 0 || openings == 0) return;
  const std::vector<Rect> windows(layout.openings.begin(),
                                  layout.openings.begin() + static_cast<std::ptrdiff_t>(openings));
  double solid = 0;
  for (const Rect& r : subtract(Rect{0, 0, layout.width, layout.height}, windows))
    solid += r.area();
  layout.open_area = (wall - solid) / wall;
  layout.notes.push_back(fmt::format("openings {:.2f} m2, {:.1f} % of the wall",
                                     (wall - solid) / 1e6, 100 * layout.open_area));
}

}  // namespace curdle
