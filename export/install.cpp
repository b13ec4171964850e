#include "export/install.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "curdle/text.h"
#include "export/wkt.h"
#include "layout/piece.h"

namespace curdle {
namespace {

// Positions to the micrometre, as in the schedule and the DXF.
std::string num(double v) { return mm_text(v); }

}  // namespace

void write_install_svg(std::ostream& out, const Layout& layout) {
  const Provenance& title = layout.source;
  const double W = layout.width, H = layout.height;
  const double unit = std::max(W, H) / 60, margin = unit * 3;
  auto x = [&](double v) { return margin + v; };
  auto y = [&](double v) { return margin + H - v; };  // the layout's y runs up
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}mm\" height=\"{1}mm\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"Helvetica, Arial, sans-serif\">\n",
      num(W + 2 * margin), num(H + 2 * margin));
  out << fmt::format("<title>{} - installation map, seed {}</title>\n", xml_escape(title.recipe),
                     title.seed);
  out << fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#ffffff\" stroke=\"#000\" "
      "stroke-width=\"{}\"/>\n",
      num(x(0)), num(y(H)), num(W), num(H), num(unit * 0.05));
  for (const auto& sheet : layout.sheets)
    out << fmt::format(
        "<g class=\"sheet\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" "
        "stroke=\"#1864ab\" stroke-width=\"{}\"/><text x=\"{}\" y=\"{}\" font-size=\"{}\" "
        "fill=\"#1864ab\">{}</text></g>\n",
        num(x(sheet.area.x)), num(y(sheet.area.top())), num(sheet.area.w), num(sheet.area.h),
        num(unit * 0.1), num(x(sheet.area.x) + unit * 0.3), num(y(sheet.area.top()) + unit),
        num(unit * 0.8), sheet.id);
  out << "<g id=\"elements\" fill=\"none\" stroke=\"#555\" stroke-width=\"" << num(unit * 0.02)
      << "\">\n";
  for (const Element& e : layout.elements) {
    const Rgb& c = piece_colour(layout, e);
    const std::string fill = fmt::format("rgb({},{},{})", c.r, c.g, c.b);
    double cx, cy, w;
    out << fmt::format("<g id=\"{}\" class=\"element\" data-row=\"{}\" data-column=\"{}\">",
                       xml_escape(e.id), e.row, e.column);
    if (e.circle) {
      cx = e.circle->cx, cy = e.circle->cy, w = e.circle->d;
      out << fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" fill-opacity=\"0.35\"/>",
                         num(x(cx)), num(y(cy)), num(e.circle->d / 2), fill);
    } else if (e.outline) {  // merged openings, cut as their union
      std::string d;
      for (const Ring& ring : e.outline->rings)
        for (size_t i = 0; i < ring.size(); ++i)
          d += fmt::format("{}{} {}{}", i ? "L" : "M", num(x(ring[i][0])), num(y(ring[i][1])),
                           i + 1 == ring.size() ? "z" : "");
      out << fmt::format("<path d=\"{}\" fill=\"{}\" fill-opacity=\"0.35\" fill-rule=\"evenodd\"/>",
                         d, fill);
      const Rect b = laid_bounds(e);
      cx = b.x + b.w / 2, cy = b.y + b.h / 2, w = std::min(b.w, b.h * 3);
    } else {
      const auto& rects = e.shape.empty() ? std::vector<Rect>{e.nominal} : e.shape;
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (const Rect& r : rects) {
        out << fmt::format(
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" "
            "fill-opacity=\"0.35\"/>",
            num(x(r.x)), num(y(r.top())), num(r.w), num(r.h), fill);
        x0 = std::min(x0, r.x), x1 = std::max(x1, r.right()), y0 = std::min(y0, r.y),
        y1 = std::max(y1, r.top());
      }
      cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, w = std::min(x1 - x0, (y1 - y0) * 3);
    }
    // The label fits the element: about 0.6 em a character.
    const double size = std::max(0.1, w / (0.62 * static_cast<double>(e.id.size()) + 1));
    out << fmt::format(
        "<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"middle\" fill=\"#000\" "
        "stroke=\"none\">{}</text></g>\n",
        num(x(cx)), num(y(cy) + size * 0.35), num(size), xml_escape(e.id));
  }
  out << "</g>\n";

  // Row numbers beside the origin side, and where laying starts.
  if (layout.kind != LayoutKind::blocks) {
    const bool right = from_right(layout.origin);
    const bool top = from_top(layout.origin);
    const auto rows = laying_extents(layout).rows;
    out << fmt::format("<g id=\"rows\" font-size=\"{}\" fill=\"#c92a2a\">\n", num(unit * 0.6));
    for (const auto& [row, extent] : rows)
      out << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"{}\">row {}</text>\n",
                         num(right ? x(W) + unit * 0.3 : x(0) - unit * 0.3),
                         num(y((extent.first + extent.second) / 2) + unit * 0.2),
                         right ? "start" : "end", row);
    out << "</g>\n";
    const double sx = right ? W : 0, sy = top ? H : 0;
    const double dx = right ? -1 : 1, dy = top ? -1 : 1;
    out << fmt::format(
        "<g id=\"laying-order\" stroke=\"#c92a2a\" stroke-width=\"{0}\" fill=\"#c92a2a\">"
        "<circle cx=\"{1}\" cy=\"{2}\" r=\"{3}\"/>"
        "<path fill=\"none\" d=\"M{1} {2}l{4} 0M{1} {2}l0 {5}\"/>"
        "<text x=\"{6}\" y=\"{7}\" stroke=\"none\" font-size=\"{8}\">start: row 0, column 0; "
        "rows run this way, columns along each row</text></g>\n",
        num(unit * 0.12), num(x(sx)), num(y(sy)), num(unit * 0.4), num(dx * unit * 4),
        num(-dy * unit * 4), num(x(sx) + dx * unit * 0.8 - (right ? unit * 20 : 0)),
        num(y(sy) + (top ? -unit : unit * 1.6)), num(unit * 0.6));
  }
  out << "</svg>\n";
}

}  // namespace curdle
