#include "export/drawing/install.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "curdle/text.h"
#include "export/drawing/sheet_drawing.h"
#include "layout/legend.h"
#include "layout/piece.h"
#include "layout/wkt.h"

namespace curdle {
namespace {

using namespace sheet_drawing;

// Positions to the micrometre, as in the schedule and the DXF.
std::string num(double v) { return mm_text(v); }

constexpr double kRowStripMm = 14, kColumnStripMm = 8, kHeadingMm = 11;  // paper mm
const char* const kRed = "#c92a2a";
const char* const kBlue = "#1864ab";

// Layout millimetres to the drawing's: x from the left of the row strip, y down from the top.
struct Frame {
  double left = 0, top = 0;  // layout mm at the drawing's top-left corner
  double x(double v) const { return v - left; }
  double y(double v) const { return top - v; }
};

// Text whose capitals are `cap` paper mm at 1 : scale, centred on (x, y) drawing units.
std::string centred_text(double x, double y, double cap, double scale, const std::string& s,
                         bool rotated, const char* fill = "#222") {
  const double size = cap / kCapHeightEm * scale;
  const std::string at =
      rotated ? fmt::format(" transform=\"rotate(-90 {} {})\"", num(x), num(y)) : std::string();
  return fmt::format(
      "<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"middle\" fill=\"{}\"{}>{}</text>",
      num(x), num(y + cap * scale / 2), num(size), fill, at, xml_escape(s));
}

// Closed rings as path data, for an even-odd fill.
std::string rings_path(const std::vector<Ring>& rings, const Frame& f) {
  std::string d;
  for (const Ring& ring : rings)
    for (size_t i = 0; i < ring.size(); ++i)
      d += fmt::format("{}{} {}{}", i ? "L" : "M", num(f.x(ring[i][0])), num(f.y(ring[i][1])),
                       i + 1 == ring.size() ? "z" : "");
  return d;
}

// A piece's shape in `fill`: its circle, its outline (merged openings, a piece cut along a
// sloping edge) or its rectangles.
void write_shape(std::ostream& out, const Element& e, const Frame& f, const std::string& fill) {
  if (e.circle) {
    out << fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"/>", num(f.x(e.circle->cx)),
                       num(f.y(e.circle->cy)), num(e.circle->d / 2), fill);
  } else if (e.outline) {
    out << fmt::format("<path d=\"{}\" fill=\"{}\" fill-rule=\"evenodd\"/>",
                       rings_path(e.outline->rings, f), fill);
  } else {
    for (const Rect& r : e.shape.empty() ? std::vector<Rect>{e.nominal} : e.shape)
      out << fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>",
                         num(f.x(r.x)), num(f.y(r.top())), num(r.w), num(r.h), fill);
  }
}

void write_element(std::ostream& out, const Layout& layout, const Element& e, const Frame& f) {
  const Rgb& c = piece_colour(layout, e);
  out << fmt::format("<g id=\"{}\" class=\"element\" data-row=\"{}\" data-column=\"{}\">",
                     xml_escape(e.id), e.row, e.column);
  write_shape(out, e, f, fmt::format("rgb({},{},{})", c.r, c.g, c.b));
  if (const std::optional<Rect> pit = tree_pit(layout, e))  // dashed, as the sheets draw it
    out << fmt::format(
        "<rect class=\"tree-pit\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" "
        "stroke=\"#222\" stroke-dasharray=\"{} {}\"/>",
        num(f.x(pit->x)), num(f.y(pit->top())), num(pit->w), num(pit->h), num(pit->w / 15),
        num(pit->w / 25));
  out << "</g>\n";
}

// The hatch a piece is drawn with, as on the PDF sheets (sheet_drawing.h): one per product
// (LegendEntry::same_as); none for value 0, a park's elements and openings.
std::optional<uint32_t> hatched(const Layout& layout, const Element& e) {
  if (!e.type.empty() || e.form == ElementForm::opening || e.value == 0) return std::nullopt;
  return layout.legend[e.value].same_as;
}

// The hatches as SVG patterns, `s` drawing units a paper millimetre: lines across a tile of
// the spacing, turned to the hatch's direction.
void write_hatch_patterns(std::ostream& out, const Layout& layout, double s) {
  out << "<defs>\n";
  for (const LegendLine& l : legend_lines(layout.legend)) {
    // The ink over the colour as drawn: faint on white paper.
    const auto faint = [](uint8_t c) {
      return static_cast<uint8_t>(std::lround(255 - (255 - c) * kFaintAlpha));
    };
    const Rgb& c = l.entry->colour;
    const std::optional<HatchStyle> h =
        hatch_style(l.entry->same_as, Rgb{faint(c.r), faint(c.g), faint(c.b)});
    if (!h) continue;
    const double t = h->spacing * s;
    std::string d = fmt::format("M0 {}H{}", num(t / 2), num(t));
    if (h->degrees.size() > 1) d += fmt::format("M{} 0V{}", num(t / 2), num(t));  // crossed
    out << fmt::format(
        "<pattern id=\"hatch-{}\" patternUnits=\"userSpaceOnUse\" width=\"{}\" height=\"{}\" "
        "patternTransform=\"rotate({})\"><path d=\"{}\" stroke=\"rgb({},{},{})\" "
        "stroke-opacity=\"{}\" stroke-width=\"{}\"/></pattern>\n",
        l.entry->same_as, num(t), num(t), num(-h->degrees.front()), d, h->ink.r, h->ink.g, h->ink.b,
        kHatchAlpha, num(kHatchLineMm * s));
  }
  out << "</defs>\n";
}

// What is laid: paper beyond the outline, the outline, openings, fabrication sheets and the
// elements.
void write_surface(std::ostream& out, const Layout& layout, const Frame& f, double s) {
  const bool outlined = !layout.outline.empty();
  out << "<g id=\"outside\" fill=\"#fff\">\n";  // beyond the outline: paper
  for (const Rect& o : layout.outside)
    out << fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>\n", num(f.x(o.x)),
                       num(f.y(o.top())), num(o.w), num(o.h));
  for (const Outline& o : layout.cut_away)  // beyond sloping edges, in sloping zones
    out << fmt::format("<path fill-rule=\"evenodd\" d=\"{}\"/>\n", rings_path(o.rings, f));
  out << "</g>\n";
  if (outlined) {
    std::string d;
    for (size_t k = 0; k < layout.outline.size(); ++k)
      d += fmt::format("{}{} {}", k ? "L" : "M", num(f.x(layout.outline[k][0])),
                       num(f.y(layout.outline[k][1])));
    out << fmt::format(
        "<path id=\"outline\" d=\"{}z\" fill=\"none\" stroke=\"#222\" stroke-width=\"{}\"/>\n", d,
        num(0.35 * s));
  }
  out << "<g id=\"openings\" fill=\"#dfeaf2\">\n";
  for (const Rect& o : layout.openings)
    out << fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>\n", num(f.x(o.x)),
                       num(f.y(o.top())), num(o.w), num(o.h));
  out << "</g>\n";
  for (const auto& sheet : layout.sheets())  // a perforated surface's fabrication sheets
    out << fmt::format(
        "<rect class=\"sheet\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#c9cdd2\" "
        "stroke=\"#555\" stroke-width=\"{}\"/>\n",
        num(f.x(sheet.area.x)), num(f.y(sheet.area.top())), num(sheet.area.w), num(sheet.area.h),
        num(0.1 * s));
  out << fmt::format(
      "<g id=\"elements\" fill-opacity=\"{}\" stroke=\"#555\" stroke-width=\"{}\">\n", kFaintAlpha,
      num(0.1 * s));
  for (const Element& e : layout.elements) write_element(out, layout, e, f);
  out << "</g>\n<g id=\"hatches\">\n";  // over the faint colours, for black-and-white prints
  for (const Element& e : layout.elements)
    if (const auto h = hatched(layout, e)) {
      write_shape(out, e, f, fmt::format("url(#hatch-{})", *h));
      out << "\n";
    }
  out << "</g>\n";
}

// The installer's sheets, each named in its match-line captions.
void write_sheet_grid(std::ostream& out, const InstallerPlan& plan, const Frame& f, double s) {
  out << fmt::format(
      "<g id=\"installer-sheets\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" "
      "stroke-dasharray=\"{} {} {} {}\">\n",
      kBlue, num(0.5 * s), num(6 * s), num(1.5 * s), num(s), num(1.5 * s));
  for (size_t i = 0; i < plan.sheets.size(); ++i) {
    const Rect& w = plan.sheets[i].window;
    out << fmt::format(
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"><title>sheet {}</title></rect>\n",
        num(f.x(w.x)), num(f.y(w.top())), num(w.w), num(w.h), installer_sheet_number(i));
  }
  out << "</g>\n<g id=\"sheet-numbers\">\n";
  for (const MatchCaption& c : plan.captions)
    out << centred_text(f.x(c.box.x + c.box.w / 2), f.y(c.box.y + c.box.h / 2), kMatchCaptionMm, s,
                        fmt::format("sheet {}", installer_sheet_number(c.sheet)), c.vertical, kBlue)
        << "\n";
  out << "</g>\n";
}

// Labels as planned (no leader crosses another label or leader): leaders first, under them.
void write_labels(std::ostream& out, const InstallerPlan& plan, const Frame& f, double s) {
  out << fmt::format("<g id=\"leaders\" stroke=\"#222\" stroke-width=\"{}\" fill=\"#222\">\n",
                     num(0.15 * s));
  for (const InstallerLabel& l : plan.labels) {
    if (l.inside) continue;
    const auto [ax, ay] = leader_end(l);
    out << fmt::format("<path d=\"M{} {}L{} {}\"/><circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>\n",
                       num(f.x(l.anchor[0])), num(f.y(l.anchor[1])), num(f.x(ax)), num(f.y(ay)),
                       num(f.x(l.anchor[0])), num(f.y(l.anchor[1])), num(kLeaderDotMm * s));
  }
  // A white halo keeps every ID clear of the lines and openings under it.
  out << fmt::format(
      "</g>\n<g id=\"labels\" paint-order=\"stroke\" stroke=\"#fff\" stroke-width=\"{}\" "
      "stroke-linejoin=\"round\">\n",
      num(0.5 * s));
  for (const InstallerLabel& l : plan.labels) {
    if (!l.inside)
      out << fmt::format(
          "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#fff\" stroke=\"#222\" "
          "stroke-width=\"{}\"/>",
          num(f.x(l.box.x)), num(f.y(l.box.top())), num(l.box.w), num(l.box.h), num(0.1 * s));
    // Two lines a label's height apart, the first above (read up the page: left).
    const std::vector<std::string> lines = label_lines(l);
    for (size_t k = 0; k < lines.size(); ++k) {
      const double step = (static_cast<double>(k) - (static_cast<double>(lines.size()) - 1) / 2) *
                          label_height_mm(plan.text_mm) * s;
      const double x = f.x(l.box.x + l.box.w / 2), y = f.y(l.box.y + l.box.h / 2);
      out << centred_text(l.rotated ? x + step : x, l.rotated ? y : y + step, plan.text_mm, s,
                          lines[k], l.rotated);
    }
    out << "\n";
  }
  out << "</g>\n";
}

// Row numbers in the strip on the left, column numbers under the grid where they read, and
// where laying starts, as on the drawing set's sheets.
void write_courses(std::ostream& out, const Layout& layout, const Rect& first, const Frame& f,
                   double s) {
  const double W = layout.width, H = layout.height;
  const LayingExtents extents = laying_extents(layout);
  const double cap = 2.5;
  out << fmt::format("<g id=\"rows\" font-size=\"{}\" fill=\"{}\">\n", num(cap / kCapHeightEm * s),
                     kRed);
  double last_at = -1e300;
  for (const auto& [row, extent] : extents.rows) {
    const double mid = (extent.first + extent.second) / 2;
    if (std::fabs(mid - last_at) < 3.2 * s) continue;
    last_at = mid;
    out << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">R{}</text>\n",
                       num(f.x(first.x) - 1.5 * s), num(f.y(mid) + cap / 2 * s), row);
  }
  last_at = -1e300;
  for (const auto& [column, extent] : extents.columns) {
    const double mid = (extent.first + extent.second) / 2;
    const std::string t = fmt::format("C{}", column);
    if (std::fabs(mid - last_at) < (label_width_mm(t.size(), cap) + 1.5) * s) continue;
    last_at = mid;
    out << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", num(f.x(mid)),
                       num(f.y(first.y) + 4.5 * s), t);
  }
  out << "</g>\n";

  // Where laying starts, as on the drawing set's sheets.
  const bool right = from_right(layout.origin), top = from_top(layout.origin);
  const double dx = right ? -1 : 1, dy = top ? 1 : -1;  // drawing y runs down
  const double ox = f.x(right ? W : 0) - dx * kStartDotMm * s;
  const double oy = f.y(top ? H : 0) - dy * kStartDotMm * s;
  out << fmt::format(
      "<g id=\"laying-order\" stroke=\"{0}\" stroke-width=\"{1}\" fill=\"{0}\">"
      "<circle cx=\"{2}\" cy=\"{3}\" r=\"{4}\"/>"
      "<path fill=\"none\" d=\"M{2} {3}l{5} 0M{2} {3}l0 {6}\"/>"
      "<text x=\"{7}\" y=\"{8}\" stroke=\"none\" font-size=\"{9}\" text-anchor=\"{10}\">{11}"
      "</text></g>\n",
      kRed, num(0.35 * s), num(ox), num(oy), num(1.2 * s), num(dx * kStartArrowMm * s),
      num(dy * kStartArrowMm * s), num(ox + dx * (kStartArrowMm + 2) * s),
      num(oy + kStartTextMm / 2 * s), num(kStartTextMm / kCapHeightEm * s), right ? "end" : "start",
      kStartText);
}

// The key beside the map: what every piece is made of, its colour and hatch as drawn (the
// pieces' faint fill), and how many; one line per product (LegendEntry::same_as).
struct KeyLine {
  Rgb colour;
  std::optional<uint32_t> hatch;
  size_t count = 0;
};
std::map<std::pair<std::string, uint32_t>, KeyLine> key_lines(const Layout& layout) {
  std::map<std::pair<std::string, uint32_t>, KeyLine> lines;  // by material, then product
  for (const Element& e : layout.elements) {
    const std::optional<uint32_t> h = hatched(layout, e);
    KeyLine& l = lines[{piece_material(layout, e), h.value_or(0)}];
    if (l.count++ == 0) l.colour = piece_colour(layout, e), l.hatch = h;
  }
  return lines;
}

constexpr double kKeyCapMm = 2.5, kKeyCharEm = 0.62;  // a character's width, in ems

// The key's width in paper mm: its longest line at about 0.62 em a character, so that no line
// runs off the drawing ("Dark brown ...: 3105" once read "310").
double key_width_mm(const Layout& layout) {
  size_t longest = 3;
  for (const auto& [what, line] : key_lines(layout))
    longest = std::max(longest, fmt::format("{}: {}", what.first, line.count).size());
  return 10 + kKeyCharEm * kKeyCapMm / kCapHeightEm * static_cast<double>(longest) + 4;
}

void write_key(std::ostream& out, const Layout& layout, double x, double y, double s) {
  const double cap = kKeyCapMm / kCapHeightEm * s, row = 6 * s;
  out << fmt::format(
      "<g id=\"key\" font-size=\"{}\" fill=\"#222\"><text x=\"{}\" y=\"{}\" "
      "font-weight=\"bold\">key</text>\n",
      num(cap), num(x), num(y));
  double at = y + row;
  for (const auto& [what, line] : key_lines(layout)) {
    const std::string box = fmt::format("x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"", num(x),
                                        num(at - 3.5 * s), num(8 * s), num(4 * s));
    out << fmt::format(
        "<rect {} fill=\"#fff\"/><rect {} fill=\"rgb({},{},{})\" fill-opacity=\"{}\"/>", box, box,
        line.colour.r, line.colour.g, line.colour.b, kFaintAlpha);
    if (line.hatch) out << fmt::format("<rect {} fill=\"url(#hatch-{})\"/>", box, *line.hatch);
    out << fmt::format(
        "<rect {} fill=\"none\" stroke=\"#222\" stroke-width=\"{}\"/><text x=\"{}\" "
        "y=\"{}\">{}: {}</text>\n",
        box, num(0.2 * s), num(x + 10 * s), num(at), xml_escape(what.first), line.count);
    at += row;
  }
  out << "</g>\n";
}

}  // namespace

void write_install_svg(std::ostream& out, const Layout& layout, const InstallerPlan& plan) {
  const Provenance& title = layout.source;
  const double s = plan.scale, W = layout.width, H = layout.height;
  const Rect& first = plan.sheets.front().window;
  const Rect& last = plan.sheets.back().window;
  // The sheets' grid, the row strip on its left, column numbers under it and a heading above.
  const Frame f{first.x - kRowStripMm * s, last.top() + kHeadingMm * s};
  const double width = last.right() + (6 + key_width_mm(layout)) * s - f.left;
  const double height = f.top - (first.y - kColumnStripMm * s);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}mm\" height=\"{}mm\" "
      "viewBox=\"0 0 {} {}\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n",
      num(width / s), num(height / s), num(width), num(height));
  out << fmt::format("<title>{} - installation map at 1 : {:g}, seed {}</title>\n",
                     xml_escape(title.recipe), s, title.seed);
  // The surface (the first rectangle: readers find the layout's frame by it).
  const bool outlined = !layout.outline.empty();  // then the outline is drawn, not the frame
  out << fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#fff\" stroke=\"{}\" "
      "stroke-width=\"{}\"/>\n",
      num(f.x(0)), num(f.y(H)), num(W), num(H), outlined ? "none" : "#222", num(0.35 * s));
  // The heading, two short lines so that it fits over the narrowest map.
  const double heading = 2.5 / kCapHeightEm * s;
  // A coursed map numbers its courses and columns; it draws no IDs to give a height for.
  const std::string what =
      plan.coursed ? "courses and columns numbered" : fmt::format("IDs {:.1f} mm", plan.text_mm);
  out << fmt::format(
      "<g id=\"heading\" font-size=\"{}\" fill=\"#222\"><text x=\"{}\" y=\"{}\" "
      "font-weight=\"bold\">{}</text><text x=\"{}\" y=\"{}\">installation map 1 : {:g}, {}; "
      "the grid: the sheets of layout.pdf</text></g>\n",
      num(heading), num(f.x(first.x)), num(3.5 * s), xml_escape(title.recipe), num(f.x(first.x)),
      num(8 * s), s, what);
  write_hatch_patterns(out, layout, s);
  write_surface(out, layout, f, s);
  if (plan.sheets.size() > 1) write_sheet_grid(out, plan, f, s);
  write_labels(out, plan, f, s);
  if (layout.kind->laid_in_courses() && layout.pattern == LayingPattern::grid)
    write_courses(out, layout, first, f, s);
  write_key(out, layout, f.x(last.right()) + 6 * s, 3.5 * s, s);
  out << "</svg>\n";
}

}  // namespace curdle
