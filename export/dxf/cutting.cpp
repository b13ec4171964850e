#include "export/dxf/cutting.h"

#include <fmt/format.h>

#include <cmath>

#include "curdle/stop.h"
#include "export/dxf/dxf_document.h"
#include "layout/contour.h"
#include "layout/piece.h"
#include "layout/title_block.h"
#include "layout/wkt.h"

namespace curdle {

std::string rolled_text(const FabricationSheet& s, double thickness) {
  return fmt::format(
      "developed blank {:.2f} x {:.2f} mm at mid-thickness; rolled to an inside radius of {:.1f} "
      "mm "
      "({:g} mm sheet), outer face {:.2f} mm along the arc",
      s.area.w * s.developed, s.area.h, s.bend_radius, thickness, s.area.w);
}

void write_sheet_dxf(const std::filesystem::path& path, const Layout& layout, int sheet) {
  const auto& s = layout.sheets()[static_cast<size_t>(sheet)];
  std::vector<DxfLayer> layers{{"OUTLINE", Rgb{0, 0, 0}, true},
                               {"OPENING_OUTLINE", Rgb{255, 0, 0}, true}};
  for (const Element& e : layout.elements)
    if (e.sheet == sheet && e.circle)
      layers.push_back({hole_layer(e.circle->d), {255, 0, 0}, true});
  layers.push_back({"ID", Rgb{0, 0, 255}, false});
  layers.push_back({"TEXT", Rgb{0, 128, 0}, true});
  // A sheet rolled to an arc is cut flat: its blank developed at mid-thickness.
  auto bx = [&](double x) { return (x - s.area.x) * s.developed; };
  DxfDocument dxf(path, layers, Rect{0, 0, s.area.w * s.developed, s.area.h});
  if (s.outline.empty()) dxf.rect("OUTLINE", Rect{0, 0, s.area.w * s.developed, s.area.h});
  if (!s.outline_contour.empty()) {  // cut to layout.outline, its arcs as bulges
    dxf.contour("OUTLINE", transformed(s.outline_contour, 1, -s.area.x, -s.area.y));
  } else {
    for (Ring ring : s.outline) {  // cut to layout.outline
      for (auto& v : ring) v[0] -= s.area.x, v[1] -= s.area.y;
      dxf.polygon("OUTLINE", ring);
    }
  }
  for (const Element& e : layout.elements) {
    stop_point();
    if (e.sheet != sheet) continue;
    if (e.circle) {
      dxf.circle(hole_layer(e.circle->d), bx(e.circle->cx), e.circle->cy - s.area.y, e.circle->d);
    } else if (e.outline) {
      for (const Ring& ring : e.outline->rings) {
        Ring moved = ring;
        for (auto& v : moved) v[0] = bx(v[0]), v[1] -= s.area.y;
        dxf.polygon("OPENING_OUTLINE", moved);
      }
    }
  }
  // Element IDs on a layer of their own (not cut): the same IDs as the SVG, glTF and CSV.
  for (const Element& e : layout.elements) {
    stop_point();
    if (e.sheet != sheet) continue;
    const Rect b = laid_bounds(e);
    dxf.text("ID", bx(b.x + b.w / 2), b.y + b.h / 2 - s.area.y, std::max(0.5, b.w / 8), e.id, true);
  }
  const double h = std::max(5.0, std::min(s.area.w, s.area.h) / 80);
  dxf.text("TEXT", h, h, h, s.id, false);
  if (s.bend_radius > 0) dxf.text("TEXT", h, 4 * h, h, rolled_text(s, layout.thickness), false);
  // The cutter needs the sheet at its own origin; the site team needs where that origin lies.
  if (layout.site_frame)
    dxf.text("ID", h, 2.5 * h, h,
             "(0, 0) = " + site_point_text(*layout.site_frame, s.area.x, s.area.y), false);
  dxf.close();
}

void write_sheet_svg(std::ostream& out, const Layout& layout, int sheet) {
  const auto& s = layout.sheets()[static_cast<size_t>(sheet)];
  const double W = s.area.w * s.developed, H = s.area.h;
  auto y = [&](double v) { return H - v; };  // SVG's y runs down
  auto bx = [&](double x) { return (x - s.area.x) * s.developed; };
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.3f}mm\" height=\"{:.3f}mm\" "
      "viewBox=\"0 0 {:.3f} {:.3f}\" fill=\"none\" stroke-width=\"0.1\">\n",
      W, H, W, H);
  out << fmt::format("<title>{}</title>\n", s.id);
  if (s.outline.empty()) {
    out << fmt::format(
        "<rect id=\"outline\" x=\"0\" y=\"0\" width=\"{:.3f}\" height=\"{:.3f}\" "
        "stroke=\"#000000\"/>\n",
        W, H);
  } else if (!s.outline_contour.empty()) {  // cut to layout.outline, its arcs as arcs
    std::string d;
    const Contour& c = s.outline_contour;
    for (size_t i = 0; i < c.size(); ++i) {
      const ContourVertex& v = c[i];
      const ContourVertex& next = c[(i + 1) % c.size()];
      if (i == 0) d += fmt::format("M{:.3f} {:.3f}", v.x - s.area.x, y(v.y - s.area.y));
      if (v.bulge == 0) {
        d += fmt::format("L{:.3f} {:.3f}", next.x - s.area.x, y(next.y - s.area.y));
        continue;
      }
      // The sheet's y runs down: a counter-clockwise arc is drawn with sweep-flag 0.
      const Arc a = arc_between(v, next);
      d += fmt::format("A{:.3f} {:.3f} 0 {} {} {:.3f} {:.3f}", a.radius, a.radius,
                       std::fabs(a.sweep) > 3.14159265358979323846 ? 1 : 0, a.sweep > 0 ? 0 : 1,
                       next.x - s.area.x, y(next.y - s.area.y));
    }
    out << fmt::format("<path id=\"outline\" d=\"{}z\" stroke=\"#000000\"/>\n", d);
  } else {  // cut to layout.outline
    std::string d;
    for (const Ring& ring : s.outline) {
      for (size_t i = 0; i < ring.size(); ++i)
        d += fmt::format("{}{:.3f} {:.3f}", i ? "L" : "M", ring[i][0] - s.area.x,
                         y(ring[i][1] - s.area.y));
      d += "z";
    }
    out << fmt::format("<path id=\"outline\" d=\"{}\" stroke=\"#000000\"/>\n", d);
  }
  out << "<g id=\"openings\" stroke=\"#ff0000\">\n";
  for (const Element& e : layout.elements) {
    stop_point();
    if (e.sheet != sheet) continue;
    if (e.circle) {
      out << fmt::format("<circle id=\"{}\" cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"{:.3f}\"/>\n", e.id,
                         bx(e.circle->cx), y(e.circle->cy - s.area.y), e.circle->d / 2);
    } else if (e.outline) {
      std::string d;
      for (const Ring& ring : e.outline->rings) {
        for (size_t i = 0; i < ring.size(); ++i)
          d += fmt::format("{}{:.3f} {:.3f}", i ? "L" : "M", bx(ring[i][0]),
                           y(ring[i][1] - s.area.y));
        d += "z";
      }
      out << fmt::format("<path id=\"{}\" d=\"{}\"/>\n", e.id, d);
    }
  }
  out << "</g>\n";
  out << fmt::format(
      "<text x=\"5\" y=\"{:.3f}\" font-size=\"{:.1f}\" fill=\"#0000ff\" "
      "stroke=\"none\">{}</text>\n",
      H - 5, std::max(5.0, std::min(W, H) / 80), s.id);
  if (s.bend_radius > 0)
    out << fmt::format(
        "<text x=\"5\" y=\"{:.3f}\" font-size=\"{:.1f}\" fill=\"#0000ff\" "
        "stroke=\"none\">{}</text>\n",
        H - 5 - 2 * std::max(5.0, std::min(W, H) / 80), std::max(5.0, std::min(W, H) / 80),
        rolled_text(s, layout.thickness));
  out << "</svg>\n";
}

}  // namespace curdle
