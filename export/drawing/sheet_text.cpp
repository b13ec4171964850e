// sheet_drawing.h's words on a sheet: lines fitted and wrapped to a width, a key's line that keeps
// its count, and the title block with its north arrow.
#include <fmt/format.h>

#include <algorithm>

#include "export/drawing/sheet_drawing.h"

namespace curdle::sheet_drawing {
namespace {

// A key's line broken in two is drawn this much smaller, so that both fit its row.
constexpr double kTwoLineScale = 0.8;

// A north arrow 9 mm tall standing on (x, y), with its N beside its head: above it, the N ran
// into the title block's last line.
void north_arrow(cairo_t* cr, double x, double y) {
  colour(cr, kInk);
  cairo_new_path(cr);
  cairo_move_to(cr, x, y - 9);
  cairo_line_to(cr, x + 2.2, y);
  cairo_line_to(cr, x, y - 2);
  cairo_close_path(cr);
  cairo_fill(cr);
  cairo_move_to(cr, x, y - 9);
  cairo_line_to(cr, x - 2.2, y);
  cairo_line_to(cr, x, y - 2);
  cairo_close_path(cr);
  cairo_set_line_width(cr, 0.25);
  cairo_stroke(cr);
  text(cr, x + 3, y - 6, "N", 2.5, Align::left, false, true);
}

}  // namespace

std::vector<std::string> fit_lines(cairo_t* cr, std::vector<std::string> lines, double width,
                                   double height) {
  for (std::string& l : lines)
    while (l.size() > 4 && text_width(cr, l, height) > width) l = l.substr(0, l.size() - 4) + "...";
  return lines;
}

std::vector<std::string> wrap_lines(cairo_t* cr, const std::vector<std::string>& lines,
                                    double width, double height, size_t most) {
  std::vector<std::string> out;
  for (size_t i = 0; i < lines.size(); ++i) {
    std::string rest = lines[i];
    // Room for the lines still to come, one each.
    while (text_width(cr, rest, height) > width && out.size() + (lines.size() - i) < most) {
      size_t cut = rest.rfind(' ');
      while (cut != std::string::npos && cut > 0 &&
             text_width(cr, rest.substr(0, cut), height) > width)
        cut = rest.rfind(' ', cut - 1);
      if (cut == std::string::npos || cut == 0) break;  // one word wider than the line
      out.push_back(rest.substr(0, cut));
      rest = rest.substr(cut + 1);
    }
    out.push_back(std::move(rest));
  }
  return fit_lines(cr, std::move(out), width, height);
}

std::vector<std::string> key_lines(cairo_t* cr, const std::string& line, double width,
                                   double height) {
  if (text_width(cr, line, height) <= width) return {line};
  const size_t colon = line.find(": ");
  if (colon == std::string::npos) return fit_lines(cr, {line}, width, height);
  const std::string name = line.substr(0, colon), count = line.substr(colon);
  // Two lines: as much of the name as fits on the first, the rest with the count on the second.
  const double small = height * kTwoLineScale;
  for (size_t cut = name.rfind(' '); cut != std::string::npos && cut > 0;
       cut = name.rfind(' ', cut - 1)) {
    const std::string first = name.substr(0, cut), second = name.substr(cut + 1) + count;
    if (text_width(cr, first, small) > width) continue;
    if (text_width(cr, second, small) <= width) return {first, second};
    break;  // the longest first line leaves too much for the second: shorten the name instead
  }
  std::string shortened = name;
  while (shortened.size() > 1 && text_width(cr, shortened + "..." + count, height) > width)
    shortened.pop_back();
  if (text_width(cr, shortened + "..." + count, height) <= width)
    return {shortened + "..." + count};
  // Too narrow for a name and its count: the count first, then what it counts, cut.
  return fit_lines(cr, {line.substr(colon + 2) + " - " + name}, width, height);
}

void key_text(cairo_t* cr, double x, double y, const std::string& line, double width,
              double height) {
  const std::vector<std::string> lines = key_lines(cr, line, width, height);
  if (lines.size() == 1) {
    text(cr, x, y, lines[0], height);
    return;
  }
  const double small = height * kTwoLineScale;
  text(cr, x, y - small * 0.6, lines[0], small);
  text(cr, x, y + small * 0.6, lines[1], small);
}

double title_width(double w) { return std::min(150.0, (w - kLeftMargin - kMargin) * 0.55); }

void title_block(cairo_t* cr, const Layout& layout, const std::vector<std::string>& title_text,
                 double w, double h, const std::string& what, double scale, size_t number,
                 size_t total, const std::string& paper) {
  const double tw = title_width(w);
  const double x = w - kMargin - tw, y = h - kMargin - kTitleStrip;
  colour(cr, kInk);
  box(cr, x, y, tw, kTitleStrip, 0.35);
  std::vector<std::string> lines = title_text;
  lines.insert(lines.begin() + 1, what);
  // The first is bold at 2.5 mm, about 1.4 times as wide as the same at 2 mm: a long title
  // gives its description a line of its own rather than an ellipsis; long lines wrap, so that
  // only what ten lines cannot hold is cut.
  // Plans carry a north arrow under the ninth line: then nine lines, else ten.
  const bool arrow = !layout.kind->upright() && !layout.block_views;
  const size_t most = arrow ? 9 : 10;
  const std::string title = lines[0];
  const size_t dash = title.find(" - ");
  if (text_width(cr, title, 2) * 1.4 > tw - 6 && dash != std::string::npos) {
    lines[0] = title.substr(0, dash);
    lines.insert(lines.begin() + 1, title.substr(dash + 3));
  }
  lines[0] = fit_lines(cr, {lines[0]}, (tw - 6) / 1.4, 2)[0];
  std::vector<std::string> rest(lines.begin() + 1, lines.end());
  rest = wrap_lines(cr, rest, tw - 6, 2, most - 1);
  lines.resize(1);
  lines.insert(lines.end(), rest.begin(), rest.end());
  for (size_t i = 0; i < lines.size() && i < most; ++i)
    text(cr, x + 3, y + 5 + 4.2 * static_cast<double>(i), lines[i], i == 0 ? 2.5 : 2, Align::left,
         false, i == 0);
  text(cr, x + 3, y + kTitleStrip - 3, fmt::format("scale 1 : {:g} on {}", scale, paper), 2.5);
  text(cr, x + tw - 3, y + kTitleStrip - 3, fmt::format("sheet {} of {}", number, total), 3.5,
       Align::right, false, true);
  // Plans carry a north arrow: +y of the layout, as its glTF and IFC take north.
  if (arrow) north_arrow(cr, x + tw * 0.55, y + kTitleStrip - 1);
}

}  // namespace curdle::sheet_drawing
