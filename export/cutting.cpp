#include "export/cutting.h"

#include <dxflib/dl_dxf.h>
#include <fmt/format.h>

#include <map>
#include <memory>

#include "curdle/error.h"

namespace curdle {
namespace {

std::string hole_layer(double d) { return fmt::format("HOLE_D{:.1f}", d); }

}  // namespace

void write_sheet_dxf(const std::filesystem::path& path, const Layout& layout, int sheet) {
  const auto& s = layout.sheets[static_cast<size_t>(sheet)];
  std::map<std::string, int> layers{
      {"0", 7}, {"OUTLINE", 7}, {"TEXT", 3}, {"OPENING_OUTLINE", 1}, {"ID", 5}};
  for (const Element& e : layout.elements)
    if (e.sheet == sheet && e.circle) layers.emplace(hole_layer(e.circle->d), 1);

  DL_Dxf dxf;
  std::unique_ptr<DL_WriterA> dw(dxf.out(path.c_str(), DL_Codes::AC1009));
  if (!dw) throw InputError("cannot write " + path.string());
  dxf.writeHeader(*dw);
  dw->sectionEnd();
  dw->sectionTables();
  dxf.writeVPort(*dw);
  dw->tableLinetypes(1);
  dxf.writeLinetype(*dw, DL_LinetypeData("CONTINUOUS", "Continuous", 0, 0, 0.0));
  dw->tableEnd();
  dw->tableLayers(static_cast<int>(layers.size()));
  for (const auto& [name, colour] : layers)
    dxf.writeLayer(*dw, DL_LayerData(name, 0), DL_Attributes("", colour, -1, "CONTINUOUS", 1.0));
  dw->tableEnd();
  dw->tableStyle(1);
  dxf.writeStyle(*dw, DL_StyleData("standard", 0, 2.5, 1.0, 0.0, 0, 2.5, "txt", ""));
  dw->tableEnd();
  dxf.writeView(*dw);
  dxf.writeUcs(*dw);
  dw->tableAppid(1);
  dxf.writeAppid(*dw, "ACAD");
  dw->tableEnd();
  dw->sectionEnd();
  dw->sectionEntities();
  const DL_Attributes outline("OUTLINE", 256, -1, "BYLAYER", 1.0);
  dxf.writePolyline(*dw, DL_PolylineData(4, 0, 0, 1), outline);
  for (const auto& [x, y] :
       {std::pair{0.0, 0.0}, {s.area.w, 0.0}, {s.area.w, s.area.h}, {0.0, s.area.h}})
    dxf.writeVertex(*dw, DL_VertexData(x, y, 0, 0));
  dxf.writePolylineEnd(*dw);
  for (const Element& e : layout.elements) {
    if (e.sheet != sheet) continue;
    if (e.circle) {
      dxf.writeCircle(
          *dw, DL_CircleData(e.circle->cx - s.area.x, e.circle->cy - s.area.y, 0, e.circle->d / 2),
          DL_Attributes(hole_layer(e.circle->d), 256, -1, "BYLAYER", 1.0));
    } else if (e.outline) {
      for (const Ring& ring : e.outline->rings) {
        dxf.writePolyline(*dw, DL_PolylineData(static_cast<int>(ring.size()), 0, 0, 1),
                          DL_Attributes("OPENING_OUTLINE", 256, -1, "BYLAYER", 1.0));
        for (const auto& v : ring)
          dxf.writeVertex(*dw, DL_VertexData(v[0] - s.area.x, v[1] - s.area.y, 0, 0));
        dxf.writePolylineEnd(*dw);
      }
    }
  }
  // Element IDs on a layer of their own (not cut): the same IDs as the SVG, glTF and CSV.
  for (const Element& e : layout.elements) {
    if (e.sheet != sheet) continue;
    const double cx = e.circle ? e.circle->cx : e.nominal.x + e.nominal.w / 2;
    const double cy = e.circle ? e.circle->cy : e.nominal.y + e.nominal.h / 2;
    const double th = e.circle ? e.circle->d / 8 : e.nominal.w / 10;
    dxf.writeText(*dw,
                  DL_TextData(cx - s.area.x, cy - s.area.y, 0, cx - s.area.x, cy - s.area.y, 0, th,
                              1, 0, 1, 2, e.id, "standard", 0),
                  DL_Attributes("ID", 256, -1, "BYLAYER", 1.0));
  }
  const double h = std::max(5.0, std::min(s.area.w, s.area.h) / 80);
  dxf.writeText(*dw, DL_TextData(h, h, 0, h, h, 0, h, 1, 0, 0, 0, s.id, "standard", 0),
                DL_Attributes("TEXT", 256, -1, "BYLAYER", 1.0));
  dw->sectionEnd();
  dw->dxfEOF();
  dw->close();
}

void write_sheet_svg(std::ostream& out, const Layout& layout, int sheet) {
  const auto& s = layout.sheets[static_cast<size_t>(sheet)];
  const double W = s.area.w, H = s.area.h;
  auto y = [&](double v) { return H - v; };  // SVG's y runs down
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.3f}mm\" height=\"{:.3f}mm\" "
      "viewBox=\"0 0 {:.3f} {:.3f}\" fill=\"none\" stroke-width=\"0.1\">\n",
      W, H, W, H);
  out << fmt::format("<title>{}</title>\n", s.id);
  out << fmt::format(
      "<rect id=\"outline\" x=\"0\" y=\"0\" width=\"{:.3f}\" height=\"{:.3f}\" "
      "stroke=\"#000000\"/>\n",
      W, H);
  out << "<g id=\"openings\" stroke=\"#ff0000\">\n";
  for (const Element& e : layout.elements) {
    if (e.sheet != sheet) continue;
    if (e.circle) {
      out << fmt::format("<circle id=\"{}\" cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"{:.3f}\"/>\n", e.id,
                         e.circle->cx - s.area.x, y(e.circle->cy - s.area.y), e.circle->d / 2);
    } else if (e.outline) {
      std::string d;
      for (const Ring& ring : e.outline->rings) {
        for (size_t i = 0; i < ring.size(); ++i)
          d += fmt::format("{}{:.3f} {:.3f}", i ? "L" : "M", ring[i][0] - s.area.x,
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
  out << "</svg>\n";
}

}  // namespace curdle
