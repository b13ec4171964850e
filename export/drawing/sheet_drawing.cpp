#include "export/drawing/sheet_drawing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <span>

#include "curdle/stop.h"
#include "export/drawing/opening_dots.h"
#include "layout/ground_colour.h"
#include "layout/installer_sheets.h"
#include "layout/piece.h"
#include "layout/title_block.h"
#include "layout/zone.h"

namespace curdle::sheet_drawing {
namespace {

constexpr const char* kFont = "DejaVu Sans";

// Text drawn unhinted with unrounded metrics on every surface. Left to the defaults, a PNG
// drawn after a PDF in the same process reused the PDF's cached font and its glyphs came out a
// pixel off, so layout.png's bytes depended on what the process had drawn before.
const cairo_font_options_t* fixed_font_options() {
  static cairo_font_options_t* options = [] {
    cairo_font_options_t* o = cairo_font_options_create();
    cairo_font_options_set_hint_style(o, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(o, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_antialias(o, CAIRO_ANTIALIAS_GRAY);
    return o;
  }();
  return options;
}

// The sheets' font, its capitals `height` mm high.
void font(cairo_t* cr, double height, bool bold) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, height / kCapHeightEm);
  cairo_set_font_options(cr, fixed_font_options());
}

}  // namespace

void draw_zones(cairo_t* cr, const Layout& layout, const View& v, bool named) {
  for (const ZoneCount& z : layout.zones) {
    if (z.polygon.empty()) continue;
    const bool value = z.rule == ZoneRule::value;
    cairo_new_path(cr);
    for (size_t i = 0; i < z.polygon.size(); ++i)
      (i ? cairo_line_to : cairo_move_to)(cr, v.x(z.polygon[i][0]), v.y(z.polygon[i][1]));
    cairo_close_path(cr);
    colour(cr, value ? Rgb{34, 34, 34} : Rgb{68, 81, 92});
    cairo_set_line_width(cr, 0.35);
    const double dashes[] = {2.0, 1.2};
    cairo_set_dash(cr, dashes, value ? 2 : 0, 0);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    if (named)
      text(cr, v.x(z.polygon[0][0]) + 1.2, v.y(z.polygon[0][1]) - 1.2,
           value ? fmt::format("{} (value {})", z.name, z.value) : z.name, 2);
  }
}

void colour(cairo_t* cr, const Rgb& c, double alpha) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

namespace {

// Saves the state, turns it as the text reads and moves to where `s` starts; the caller draws
// and restores.
void begin_text(cairo_t* cr, double x, double y, const std::string& s, double height, Align align,
                bool rotated, bool bold) {
  font(cr, height, bold);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  const double shift = align == Align::left     ? 0
                       : align == Align::centre ? e.x_advance / 2
                                                : e.x_advance;
  cairo_save(cr);
  cairo_translate(cr, x, y);
  if (rotated) cairo_rotate(cr, -M_PI / 2);
  cairo_move_to(cr, -shift, 0);
}

}  // namespace

void text(cairo_t* cr, double x, double y, const std::string& s, double height, Align align,
          bool rotated, bool bold) {
  begin_text(cr, x, y, s, height, align, rotated, bold);
  cairo_show_text(cr, s.c_str());
  cairo_restore(cr);
}

void text_on_halo(cairo_t* cr, double x, double y, const std::string& s, double height, Align align,
                  bool rotated) {
  begin_text(cr, x, y, s, height, align, rotated, false);
  double px = 0, py = 0;
  cairo_get_current_point(cr, &px, &py);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  // The halo is a box round the ink, not the glyphs' outlines stroked wide: those outlines
  // were most of a sheet's bytes and of the time it took to write.
  const double pad = height * 0.14;
  cairo_rectangle(cr, px + e.x_bearing - pad, py + e.y_bearing - pad, e.width + 2 * pad,
                  e.height + 2 * pad);
  colour(cr, Rgb{255, 255, 255}, 0.9);
  cairo_fill(cr);
  // The ink as text: a reader finds an ID by searching the PDF for it.
  colour(cr, kInk);
  cairo_move_to(cr, px, py);
  cairo_show_text(cr, s.c_str());
  cairo_restore(cr);
}

double text_width(cairo_t* cr, const std::string& s, double height) {
  font(cr, height, false);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  return e.x_advance;
}

void box(cairo_t* cr, double x, double y, double w, double h, double line) {
  cairo_rectangle(cr, x, y, w, h);
  cairo_set_line_width(cr, line);
  cairo_stroke(cr);
}

// The flat pieces of a drawing: a rectangle, or an outline with its holes. Where pieces meet
// (no joints), by colour in the order the colours first come, each colour one path filled once,
// so that a reader that smooths each fill's edges leaves no light seam between two pieces of a
// material; with joints between them, each filled as it comes (a smaller, faster PDF).
class FlatFills {
 public:
  struct Shape {
    Rect rect;
    const Outline* outline = nullptr;
  };
  FlatFills(cairo_t* cr, const View& v, double alpha, bool meeting)
      : cr_(cr), v_(v), alpha_(alpha), meeting_(meeting) {}
  void add(const Rgb& c, const Shape& shape) {
    if (!meeting_) return fill(c, std::span<const Shape>(&shape, 1));  // no copy a piece
    const uint32_t key = uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b;
    const auto [at, added] = index_.try_emplace(key, fills_.size());
    if (added) fills_.push_back({c, {}});
    fills_[at->second].second.push_back(shape);
  }
  void draw() const {
    for (const auto& [c, shapes] : fills_) stop_point(), fill(c, shapes);
  }

 private:
  // One path; even-odd, so that an outline's holes stay open (pieces never overlap).
  void fill(const Rgb& c, std::span<const Shape> shapes) const {
    colour(cr_, c, alpha_);
    cairo_new_path(cr_);
    bool outlines = false;
    for (const Shape& s : shapes) {
      if (s.outline)
        add_rings(cr_, s.outline->rings, v_), outlines = true;
      else
        v_.rect(cr_, s.rect);
    }
    cairo_set_fill_rule(
        cr_, outlines || shapes.size() > 1 ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
    cairo_fill(cr_);
    cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_WINDING);
  }

  cairo_t* cr_;
  const View& v_;
  double alpha_;
  bool meeting_;
  std::map<uint32_t, size_t> index_;
  std::vector<std::pair<Rgb, std::vector<Shape>>> fills_;
};

// The layout's pieces as vectors; `faint` washes the colours out so that labels read over them.
void draw_pieces(cairo_t* cr, const Layout& layout, const View& v, bool faint) {
  const double alpha = faint ? kFaintAlpha : 1;
  const Rect all{0, 0, layout.width, layout.height};
  colour(cr, ground_colour(layout), faint ? 0.25 : 1);
  v.rect(cr, all);
  cairo_fill(cr);
  colour(cr, Rgb{223, 234, 242});
  for (const Rect& o : layout.openings) v.rect(cr, o), cairo_fill(cr);
  colour(cr, Rgb{255, 255, 255});  // beyond the outline: paper
  for (const Rect& o : layout.outside) v.rect(cr, o), cairo_fill(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);  // beyond sloping edges, in sloping zones
  for (const Outline& o : layout.cut_away) ring_paths(cr, o.rings, v), cairo_fill(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  if (layout.block_views) {  // blocks are drawn as their views
    for (const BlockViews::Cell& c : layout.block_views->cells) {
      colour(cr, layout.legend[c.value].colour, alpha);
      v.rect(cr, c.rect);
      cairo_fill(cr);
    }
    return;
  }
  FlatFills flat(cr, v, alpha, layout.joint <= 0);
  OpeningDots dots;
  for_each_element(layout, v, [&](const Element& e) {
    stop_point();
    if (!v.shows(laid_bounds(e))) return;
    const Rgb& c = e.type.empty() ? layout.legend[e.value].colour : e.colour;
    if (OpeningDots::takes(e)) return dots.add(e, c, v);  // drawn after the rest, as dots
    if (e.circle) return;                                 // a park's round object: below
    if (e.outline) return flat.add(c, {Rect{}, &*e.outline});
    if (!e.type.empty()) {
      for (const Rect& r : e.shape) flat.add(c, {r, nullptr});
      return;
    }
    for (const ColouredRect& stripe : keep_stripes(layout, e))
      flat.add(stripe.colour, {stripe.rect, nullptr});
  });
  flat.draw();
  // What stands on them: a park's round objects, and the tree pits dashed, as dug below ground.
  for_each_element(layout, v, [&](const Element& e) {
    if (!e.circle || OpeningDots::takes(e) || !v.shows(laid_bounds(e))) return;
    colour(cr, e.type.empty() ? layout.legend[e.value].colour : e.colour, alpha);
    cairo_new_path(cr);
    cairo_arc(cr, v.x(e.circle->cx), v.y(e.circle->cy), e.circle->d / 2 / v.scale, 0, 2 * M_PI);
    cairo_fill(cr);
  });
  colour(cr, kInk);  // a bench's backrest, so that the way it faces reads
  cairo_set_line_width(cr, 0.35);
  for_each_element(layout, v, [&](const Element& e) {
    if (const auto back = back_edge(e); back && v.shows(laid_bounds(e))) {
      cairo_move_to(cr, v.x((*back)[0][0]), v.y((*back)[0][1]));
      cairo_line_to(cr, v.x((*back)[1][0]), v.y((*back)[1][1]));
      cairo_stroke(cr);
    }
  });
  for_each_element(layout, v, [&](const Element& e) {
    const std::optional<Rect> pit = tree_pit(layout, e);
    if (!pit || !v.shows(laid_bounds(e))) return;
    colour(cr, kInk);
    const double dash[] = {1.0, 0.6};
    cairo_set_dash(cr, dash, 2, 0);
    cairo_set_line_width(cr, 0.2);
    v.rect(cr, *pit);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
  });
  dots.draw(cr, alpha);
}

void ring_paths(cairo_t* cr, const std::vector<Ring>& rings, const View& v) {
  cairo_new_path(cr);
  add_rings(cr, rings, v);
}

std::optional<HatchStyle> hatch_style(uint32_t value, const Rgb& under) {
  if (value == 0) return std::nullopt;
  // Directions of the lines (degrees from the paper's x axis), per value within each eight.
  static const std::vector<std::vector<double>> kStyles = {{45}, {135},   {45, 135}, {0},
                                                           {90}, {0, 90}, {45}};
  const size_t round = (value - 1) / kStyles.size();
  const size_t style = (value - 1) % kStyles.size();
  HatchStyle h;
  h.degrees = kStyles[style];
  h.spacing = (style + 1 == kStyles.size() ? 0.6 : 1.2) + 0.6 * static_cast<double>(round);
  const double luminance = 0.299 * under.r + 0.587 * under.g + 0.114 * under.b;
  h.ink = luminance < 110 ? Rgb{255, 255, 255} : kInk;
  return h;
}

void hatch(cairo_t* cr, uint32_t value, const Rgb& under, double x0, double y0, double x1,
           double y1) {
  const std::optional<HatchStyle> h = hatch_style(value, under);
  if (!h) return;
  colour(cr, h->ink, kHatchAlpha);
  cairo_set_line_width(cr, kHatchLineMm);
  const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const double reach = std::hypot(x1 - x0, y1 - y0) / 2 + h->spacing;
  for (const double degrees : h->degrees) {
    const double a = degrees * M_PI / 180, dx = std::cos(a), dy = -std::sin(a);
    for (double t = -reach; t <= reach; t += h->spacing) {  // offsets along the normal (-dy, dx)
      const double px = cx - dy * t, py = cy + dx * t;
      cairo_move_to(cr, px - dx * reach, py - dy * reach);
      cairo_line_to(cr, px + dx * reach, py + dy * reach);
    }
  }
  cairo_stroke(cr);
}

void draw_hatches(cairo_t* cr, const Layout& layout, const View& v) {
  std::map<uint32_t, std::vector<const Element*>> by_value;
  for_each_element(layout, v, [&](const Element& e) {
    // Values that lay the same product share a hatch, as they share a key line.
    if (e.value != 0 && v.shows(laid_bounds(e)))
      by_value[e.type.empty() ? layout.legend[e.value].same_as : e.value].push_back(&e);
  });
  const double x0 = v.x(v.window.x), x1 = v.x(v.window.right());
  const double y0 = v.y(v.window.top()), y1 = v.y(v.window.y);
  for (const auto& [value, elements] : by_value) {
    stop_point();
    cairo_save(cr);
    cairo_new_path(cr);
    for (const Element* e : elements) {
      if (e->circle) {
        cairo_new_sub_path(cr);
        cairo_arc(cr, v.x(e->circle->cx), v.y(e->circle->cy), e->circle->d / 2 / v.scale, 0,
                  2 * M_PI);
      } else if (e->outline) {
        add_rings(cr, e->outline->rings, v);
      } else {
        for (const Rect& r : e->shape.empty() ? std::vector<Rect>{laid_bounds(*e)} : e->shape)
          v.rect(cr, r);
      }
    }
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    cairo_clip(cr);
    hatch(cr, value, piece_colour(layout, *elements.front()), x0, y0, x1, y1);
    cairo_restore(cr);
  }
}

void add_rings(cairo_t* cr, const std::vector<Ring>& rings, const View& v) {
  // Corners are left out while every one left out lies within a hundredth of a paper
  // millimetre of the line drawn past it: a round opening polygonised to a fraction of a
  // millimetre has ten times the corners a drawing at 1:20 can show, and its path was most of
  // a perforated sheet's PDF. At most kRun in a row, so that a long straight run stays linear.
  constexpr double kPaperTolerance = 0.01;  // mm
  constexpr size_t kRun = 64;
  for (const Ring& ring : rings) {
    const size_t n = ring.size();
    auto at = [&](size_t i) {
      return std::array<double, 2>{v.x(ring[i % n][0]), v.y(ring[i % n][1])};
    };
    size_t kept = 0;
    cairo_move_to(cr, v.x(ring[0][0]), v.y(ring[0][1]));
    for (size_t i = 1; i < n; ++i) {
      // Can the line from the last corner drawn run on to i + 1, past i and those before it?
      const std::array<double, 2> from = at(kept), to = at(i + 1);
      bool passes = i - kept < kRun;
      for (size_t j = kept + 1; passes && j <= i; ++j)
        passes = distance_to_segment(at(j), from, to) < kPaperTolerance;
      if (passes) continue;
      const std::array<double, 2> p = at(i);
      cairo_line_to(cr, p[0], p[1]);
      kept = i;
    }
    cairo_close_path(cr);
  }
}

void draw_boundary(cairo_t* cr, const Layout& layout, const View& v) {
  if (layout.width <= 0 || layout.height <= 0) return;
  cairo_save(cr);
  colour(cr, kInk);
  cairo_set_line_width(cr, 0.5);
  if (layout.outline.empty()) {
    cairo_new_path(cr);
    v.rect(cr, Rect{0, 0, layout.width, layout.height});
  } else {
    ring_paths(cr, {layout.outline}, v);
  }
  cairo_stroke(cr);
  cairo_restore(cr);
}

// A white ISO sheet with its frame (ISO 5457 margins) and the line above the title strip.
void frame(cairo_t* cr, double w, double h) {
  colour(cr, Rgb{255, 255, 255});
  cairo_paint(cr);
  colour(cr, kInk);
  box(cr, kLeftMargin, kMargin, w - kLeftMargin - kMargin, h - 2 * kMargin, 0.5);
  cairo_move_to(cr, kLeftMargin, h - kMargin - kTitleStrip);
  cairo_line_to(cr, w - kMargin, h - kMargin - kTitleStrip);
  cairo_set_line_width(cr, 0.35);
  cairo_stroke(cr);
}

// A scale bar of whole metres (or tenths) that reads at 1 : scale, at most `room` mm long.
void scale_bar(cairo_t* cr, double x, double y, double scale, double room) {
  double step = 1;  // mm of the layout per division
  for (const double s : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0, 2000.0,
                         5000.0, 10000.0, 20000.0, 50000.0, 100000.0})
    if (4 * s / scale <= room) step = s;
  const double d = step / scale;
  for (int i = 0; i < 4; ++i) {
    cairo_rectangle(cr, x + i * d, y, d, 1.6);
    colour(cr, i % 2 ? Rgb{255, 255, 255} : kInk);
    cairo_fill_preserve(cr);
    colour(cr, kInk);
    cairo_set_line_width(cr, 0.2);
    cairo_stroke(cr);
  }
  auto label = [&](double v) {
    return v == 0      ? std::string("0")
           : v >= 1000 ? fmt::format("{:g} m", v / 1000)
                       : fmt::format("{:g} mm", v);
  };
  for (int i = 0; i <= 4; i += 2) text(cr, x + i * d, y - 1.2, label(i * step), 2, Align::centre);
}

// Where laying starts: a red dot just outside the origin corner, and arrows along the first
// row and up the rows, clear of the first element.
void start_corner(cairo_t* cr, const Layout& layout, const View& v) {
  if (!layout.kind->laid_from_corner()) return;
  const bool right = from_right(layout.origin), top = from_top(layout.origin);
  const double cx = v.x(right ? layout.width : 0), cy = v.y(top ? layout.height : 0);
  const double dx = right ? -1 : 1, dy = top ? 1 : -1;  // paper y runs down
  const double ox = cx - dx * kStartDotMm, oy = cy - dy * kStartDotMm;
  colour(cr, kRed);
  cairo_new_path(cr);  // no line from where the last text ended
  cairo_arc(cr, ox, oy, 1.2, 0, 2 * M_PI);
  cairo_fill(cr);
  cairo_set_line_width(cr, 0.35);
  cairo_move_to(cr, ox, oy);
  cairo_line_to(cr, ox + dx * kStartArrowMm, oy);
  cairo_move_to(cr, ox, oy);
  cairo_line_to(cr, ox, oy + dy * kStartArrowMm);
  cairo_stroke(cr);
  text(cr, ox + dx * (kStartArrowMm + 2), oy + kStartTextMm / 2, kStartText, kStartTextMm,
       right ? Align::right : Align::left);
}

void draw_facades(cairo_t* cr, const Layout& layout, const View& v) {
  if (!layout.envelope) return;
  const double bottom = v.y(0), top = v.y(layout.height);
  const double below = bottom + kStartDotMm + 1.25;  // in line with the start corner's words
  // Clear of those words where the strip starts on this sheet.
  const double clear = v.shows(Rect{0, 0, 0, 0})
                           ? v.x(0) + kStartArrowMm + 4 + text_width(cr, kStartText, kStartTextMm)
                           : -1e300;
  cairo_save(cr);
  colour(cr, kBlue);
  cairo_set_line_width(cr, 0.35);
  const double dash[] = {2.0, 1.0};
  for (const SurfaceFrame& f : layout.frames()) {
    const double from = std::max(f.start, v.window.x);
    const double to = std::min(f.start + f.length, v.window.right());
    if (to <= from) continue;
    // The corner at the façade's end, dashed up the wall and down to the names.
    const double end = f.start + f.length;
    if (end >= v.window.x && end <= v.window.right() && !f.last_of_path) {
      cairo_set_dash(cr, dash, 2, 0);
      cairo_move_to(cr, v.x(end), top);
      cairo_line_to(cr, v.x(end), below + 1);
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
    }
    std::string name = f.name;
    name += f.bulge != 0 ? " (curved), " : ", ";
    name += fmt::format("{:g} mm", std::round(f.length * 10) / 10);
    const double left = std::max(v.x(from), clear), right = v.x(to);
    for (const std::string& said : {name, f.name})
      if (right - left > text_width(cr, said, 2.5) + 3) {
        text_on_halo(cr, (left + right) / 2, below, said, 2.5, Align::centre);
        break;
      }
  }
  cairo_restore(cr);
}

}  // namespace curdle::sheet_drawing
