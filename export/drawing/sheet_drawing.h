// Drawing on an ISO sheet with cairo, in millimetres: the pen (colours, the sheets' font, text
// set by its capital height), the view that places layout millimetres on paper, and the parts
// every sheet of the drawing set shares: the frame, the pieces, the scale bar, the start corner
// and the title block.
#pragma once

#include <cairo.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "layout/layout.h"

namespace curdle::sheet_drawing {

inline constexpr double kPointsPerMm = 72 / 25.4;
inline constexpr double kLeftMargin = 20, kMargin = 10, kTitleStrip = 50;  // drawing_sheet.h
inline const Rgb kInk{34, 34, 34}, kRed{201, 42, 42}, kBlue{24, 100, 171};

void colour(cairo_t* cr, const Rgb& c, double alpha = 1);

// Text whose capitals are `height` mm, its left end (or centre, or right end) at x, its
// baseline at y; turned to read bottom to top when `rotated`.
enum class Align { left, centre, right };
void text(cairo_t* cr, double x, double y, const std::string& s, double height,
          Align align = Align::left, bool rotated = false, bool bold = false);
// The same in ink on a white halo, so that a line under it (a zone's dashed outline, a joint)
// does not strike through it.
void text_on_halo(cairo_t* cr, double x, double y, const std::string& s, double height,
                  Align align = Align::left, bool rotated = false);
double text_width(cairo_t* cr, const std::string& s, double height);
// Each line cut short with "..." where it is wider than `width` mm at `height`.
std::vector<std::string> fit_lines(cairo_t* cr, std::vector<std::string> lines, double width,
                                   double height);
// The lines broken at spaces where they are wider than `width` mm at `height`, a break's rest
// on a line of its own, up to `most` lines; only what still does not fit is cut with "...".
std::vector<std::string> wrap_lines(cairo_t* cr, const std::vector<std::string>& lines,
                                    double width, double height, size_t most);

// A key's or legend's line, "what: how many", within `width` mm at `height`: whole when it fits;
// else the name broken at a space onto a second line; else the name cut with "..." before the
// colon. The count is never cut: where even "...: count" is too wide, the count comes first.
std::vector<std::string> key_lines(cairo_t* cr, const std::string& line, double width,
                                   double height);
// key_lines drawn with the first line's baseline at `y` (two lines a little smaller, the second
// below it).
void key_text(cairo_t* cr, double x, double y, const std::string& line, double width,
              double height);

void box(cairo_t* cr, double x, double y, double w, double h, double line);

// Where layout millimetres land on paper: the window's top-left corner at (left, top).
struct View {
  Rect window;
  double scale = 1;
  double left = 0, top = 0;
  // The layout's elements that may show, by index, when the caller knows them (an installer's
  // sheet of a large set); else every element is tested.
  const std::vector<uint32_t>* elements = nullptr;
  double x(double v) const { return left + (v - window.x) / scale; }
  double y(double v) const { return top + (window.top() - v) / scale; }
  bool shows(const Rect& r) const {
    return r.right() >= window.x && r.x <= window.right() && r.top() >= window.y &&
           r.y <= window.top();
  }
  void rect(cairo_t* cr, const Rect& r) const {
    cairo_rectangle(cr, x(r.x), y(r.top()), r.w / scale, r.h / scale);
  }
};

// Calls f(element) for each element of the layout that may show in `v`, shown or not.
template <class F>
void for_each_element(const Layout& layout, const View& v, F&& f) {
  if (!v.elements) {
    for (const Element& e : layout.elements) f(e);
    return;
  }
  for (const uint32_t i : *v.elements) f(layout.elements[i]);
}

// The layout's pieces as vectors; `faint` washes the colours out so that labels read over them.
// Installer's sheets draw pieces faint, so that IDs read on them; their keys show them so.
inline constexpr double kFaintAlpha = 0.35;
void draw_pieces(cairo_t* cr, const Layout& layout, const View& v, bool faint);

// A building's façades on its unrolled strip: each corner dashed up the wall, and each façade
// named under it with its length, as far as `v` shows them.
void draw_facades(cairo_t* cr, const Layout& layout, const View& v);

// The layout's zones ([[layout.zones]]) as layout.svg draws them: outlined, value zones dashed,
// and named (with their value) when `named`; installer's sheets draw the outlines alone, so that
// no name lies on an ID.
void draw_zones(cairo_t* cr, const Layout& layout, const View& v, bool named);

// Closed paths along `rings` (layout mm) added to the current path; ring_paths starts a new
// one, ready to fill or stroke.
void add_rings(cairo_t* cr, const std::vector<Ring>& rings, const View& v);
void ring_paths(cairo_t* cr, const std::vector<Ring>& rings, const View& v);

// A hatch per value, so that a coursed set reads in black and white too: value 0 plain, then
// one diagonal, the other, both, level lines, upright lines, a square grid and close
// diagonals, wider apart for each further eight values; in ink over light colours and in
// white over dark ones. `hatch` fills the current clip within the paper box (x0, y0)-(x1, y1).
struct HatchStyle {
  std::vector<double> degrees;  // the lines' directions from the paper's x axis, anticlockwise
  double spacing = 0;           // paper mm between lines
  Rgb ink;                      // with kHatchAlpha
};
inline constexpr double kHatchAlpha = 0.85;
inline constexpr double kHatchLineMm = 0.12;
// The hatch of a value over a colour (none for value 0): what the PDF sheets and install.svg
// both draw, so that a key reads the same on either.
std::optional<HatchStyle> hatch_style(uint32_t value, const Rgb& under);
void hatch(cairo_t* cr, uint32_t value, const Rgb& under, double x0, double y0, double x1,
           double y1);
// Every element in view hatched by its value, over draw_pieces.
void draw_hatches(cairo_t* cr, const Layout& layout, const View& v);

// The surface's boundary, its outline or its rectangle, in a heavy line: where setting out ends.
void draw_boundary(cairo_t* cr, const Layout& layout, const View& v);

// A white ISO sheet with its frame (ISO 5457 margins) and the line above the title strip.
void frame(cairo_t* cr, double w, double h);

// A scale bar of whole metres (or tenths) that reads at 1 : scale, at most `room` mm long.
void scale_bar(cairo_t* cr, double x, double y, double scale, double room);

// Where laying starts: a red dot just outside the origin corner, and arrows along the first
// row and up the rows, clear of the first element.
void start_corner(cairo_t* cr, const Layout& layout, const View& v);

// Setting out, as ordinate dimensions from the datum (the surface's bottom-left corner, 0, 0):
// the x of every edge of the surface, its outline's corners, its openings and its zones along
// the long side away from the start corner, their y along the other side, in mm, each with a
// tick (those closer than a text's height to the last drawn are left out), and a caption that
// names the datum and the corner where laying starts. An arc is set out by its centre and ends,
// a free curve by offsets at regular stations (curve_stations.h), listed under the caption as
// far as `bottom` (paper mm) leaves room.
void setting_out(cairo_t* cr, const Layout& layout, const View& v, double bottom);

// The title block's width on a sheet `w` mm wide: 150 mm, less on narrow portrait sheets.
double title_width(double w);
// The title block at the right of the strip: the title lines (title_lines(layout), worked out
// once for a set: they count the layout's cut pieces), what the sheet shows, the scale and the
// sheet number.
void title_block(cairo_t* cr, const Layout& layout, const std::vector<std::string>& title_text,
                 double w, double h, const std::string& what, double scale, size_t number,
                 size_t total, const std::string& paper);

}  // namespace curdle::sheet_drawing
