#include "export/dxf/dxf_document.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "curdle/error.h"
#include "curdle/text.h"
#include "layout/wkt.h"
#include "layout/zone.h"

namespace curdle {
namespace {

DL_Attributes on_layer(const std::string& layer) {
  return DL_Attributes(dxf_layer_name(layer), 256, -1, "BYLAYER", 1.0);
}

// The AutoCAD colour index nearest a colour, for programs that ignore true colour.
int nearest_aci(const Rgb& c) {
  const int grey = (c.r + c.g + c.b) / 3;
  const int spread = std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b});
  if (spread < 24) return grey > 200 ? 7 : grey > 150 ? 9 : grey > 90 ? 8 : 250;
  if (c.r >= c.g && c.r >= c.b) return c.g > c.r * 0.7 ? 2 : c.b > c.r * 0.7 ? 6 : 1;
  if (c.g >= c.r && c.g >= c.b) return c.b > c.g * 0.7 ? 4 : 3;
  return c.r > c.b * 0.7 ? 6 : 5;
}

}  // namespace

std::string hole_layer(double diameter) { return "HOLE_D" + mm_text(diameter); }

namespace {

// `text` for a DXF of AutoCAD 2007, whose strings are UTF-8 whatever the code page: every
// letter as it is, in any script (Grès cérame, Łódź, Ψ, 瓦, an emoji beyond the BMP), which
// ezdxf, GDAL, FreeCAD and LibreCAD all decode so. `forbidden` and control characters (a line
// break would start a group code of its own) become `instead`; bytes that are not UTF-8 too.
std::string dxf_encoded(const std::string& text, std::string_view forbidden, char instead) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const size_t start = i;
    const uint32_t c = next_code_point(text, i);
    if (c == 0xFFFD && i - start == 1)  // a byte that is not UTF-8
      out += instead;
    else if (c >= 0x80)
      out.append(text, start, i - start);
    else if (c < 0x20 || c == 0x7F || forbidden.find(static_cast<char>(c)) != std::string::npos)
      out += instead;
    else
      out += static_cast<char>(c);
  }
  return out;
}

}  // namespace

std::string dxf_layer_name(const std::string& name) {
  // No dots either: some CAD programs read one as a path separator.
  const std::string out = dxf_encoded(name, "<>/\\\":;?*|=,`.", '_');
  return out.empty() ? "_" : out;
}

std::string dxf_text(const std::string& text) { return dxf_encoded(text, "", ' '); }

DxfDocument::DxfDocument(const std::filesystem::path& path, const std::vector<DxfLayer>& layers,
                         const Rect& mm_extents, const std::optional<SiteFrame>& frame)
    : frame_(frame) {
  const Rect extents{x(mm_extents.x), y(mm_extents.y), length(mm_extents.w), length(mm_extents.h)};
  // Entities as dxflib writes them for AutoCAD 2000 (their form is the same in 2007), under a
  // 2007 header ($ACADVER AC1021): readers then take every string as UTF-8.
  path_ = path;
  dw_ = std::make_unique<BufferedDxfWriter>(path);
  if (dw_->failed()) throw InputError("cannot write " + path.string());
  DL_WriterA& dw = *dw_;
  dw.sectionHeader();
  dw.dxfString(9, "$ACADVER");
  dw.dxfString(1, "AC1021");
  dw.dxfString(9, "$HANDSEED");
  dw.dxfHex(5, 0xFFFF);
  dw.dxfString(9, "$DWGCODEPAGE");  // what AutoCAD 2007 writes; its strings are UTF-8 regardless
  dw.dxfString(3, "ANSI_1252");
  // Millimetres, metric, and where the drawing lies, so that it opens at true size and in view.
  dw.dxfString(9, "$INSUNITS");
  dw.dxfInt(70, frame_ ? frame_->insunits : 4);
  dw.dxfString(9, "$MEASUREMENT");
  dw.dxfInt(70, frame_ && (frame_->insunits == 1 || frame_->insunits == 2) ? 0 : 1);
  dw.dxfString(9, "$LUNITS");
  dw.dxfInt(70, 2);
  dw.dxfString(9, "$EXTMIN");
  dw.coord(10, extents.x, extents.y, 0);
  dw.dxfString(9, "$EXTMAX");
  dw.coord(10, extents.right(), extents.top(), 0);
  dw.dxfString(9, "$LIMMIN");
  dw.dxfReal(10, extents.x);
  dw.dxfReal(20, extents.y);
  dw.dxfString(9, "$LIMMAX");
  dw.dxfReal(10, extents.right());
  dw.dxfReal(20, extents.top());
  dw.sectionEnd();

  dw.sectionTables();
  dxf_.writeVPort(dw);
  dw.tableLinetypes(3);
  dxf_.writeLinetype(dw, DL_LinetypeData("BYBLOCK", "BYBLOCK", 0, 0, 0.0));
  dxf_.writeLinetype(dw, DL_LinetypeData("BYLAYER", "BYLAYER", 0, 0, 0.0));
  dxf_.writeLinetype(dw, DL_LinetypeData("CONTINUOUS", "Continuous", 0, 0, 0.0));
  dw.tableEnd();
  std::vector<DxfLayer> all{{"0", Rgb{255, 255, 255}, true}};
  for (const DxfLayer& l : layers)
    if (std::none_of(all.begin(), all.end(), [&](const DxfLayer& a) {
          return dxf_layer_name(a.name) == dxf_layer_name(l.name);
        }))
      all.push_back(l);
  dw.tableLayers(static_cast<int>(all.size()));
  for (const DxfLayer& l : all) {
    const std::string name = dxf_layer_name(l.name);
    const int aci = name == "0" ? 7 : nearest_aci(l.colour);
    if (l.plot) {
      DL_Attributes a(std::string(), aci,
                      name == "0" ? -1 : (l.colour.r << 16 | l.colour.g << 8 | l.colour.b), -3,
                      "CONTINUOUS");
      dxf_.writeLayer(dw, DL_LayerData(name, 0), a);
      continue;
    }
    // dxflib marks only "defpoints" as not plotted: write this entry's plot flag (290) here.
    dw.tableLayerEntry();
    dw.dxfString(2, name);
    dw.dxfInt(70, 0);
    dw.dxfInt(62, aci);
    dw.dxfString(6, "CONTINUOUS");
    dw.dxfInt(290, 0);
    dw.dxfInt(370, -3);
    dw.dxfHex(390, 0xF);
  }
  dw.tableEnd();
  dw.tableStyle(1);
  // Named "Standard": dxflib refers the dimension style to the style of that exact name.
  dxf_.writeStyle(dw, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
  dw.tableEnd();
  dxf_.writeView(dw);
  dxf_.writeUcs(dw);
  dw.tableAppid(1);
  dxf_.writeAppid(dw, "ACAD");
  dw.tableEnd();
  dxf_.writeDimStyle(dw, 1, 1, 1, 1, 1);
  // The block records of model and paper space only, with dxflib's handles for them (its
  // BLOCK section refers to them). dxflib's own table adds a second paper space and its
  // OBJECTS section dictionaries without owners, which CAD programs then have to repair;
  // without them the file audits clean.
  dw.dxfString(0, "TABLE");
  dw.dxfString(2, "BLOCK_RECORD");
  dw.dxfHex(5, 1);
  dw.dxfString(100, "AcDbSymbolTable");
  dw.dxfInt(70, 2);
  for (const auto& [handle, name] : {std::pair{0x1F, "*Model_Space"}, {0x1B, "*Paper_Space"}}) {
    dw.dxfString(0, "BLOCK_RECORD");
    dw.dxfHex(5, handle);
    dw.dxfString(100, "AcDbSymbolTableRecord");
    dw.dxfString(100, "AcDbBlockTableRecord");
    dw.dxfString(2, name);
  }
  dw.tableEnd();
  dw.sectionEnd();
  dw.sectionBlocks();
  for (const char* space : {"*Model_Space", "*Paper_Space"}) {
    dxf_.writeBlock(dw, DL_BlockData(space, 0, 0.0, 0.0, 0.0));
    dxf_.writeEndBlock(dw, space);
  }
  dw.sectionEnd();
  dw.sectionEntities();
}

DxfDocument::~DxfDocument() = default;

void DxfDocument::polygon(const std::string& layer, const Ring& ring) {
  dxf_.writePolyline(*dw_, DL_PolylineData(static_cast<int>(ring.size()), 0, 0, 1),
                     on_layer(layer));
  for (const auto& v : ring) dxf_.writeVertex(*dw_, DL_VertexData(x(v[0]), y(v[1]), 0, 0));
  dxf_.writePolylineEnd(*dw_);
}

void DxfDocument::contour(const std::string& layer, const Contour& c) {
  if (c.size() == 2 && c[0].bulge == c[1].bulge && std::fabs(c[0].bulge) == 1) {
    circle(layer, (c[0].x + c[1].x) / 2, (c[0].y + c[1].y) / 2,
           std::hypot(c[1].x - c[0].x, c[1].y - c[0].y));
    return;
  }
  dxf_.writePolyline(*dw_, DL_PolylineData(static_cast<int>(c.size()), 0, 0, 1), on_layer(layer));
  for (const ContourVertex& v : c)
    dxf_.writeVertex(*dw_, DL_VertexData(x(v.x), y(v.y), 0, v.bulge));
  dxf_.writePolylineEnd(*dw_);
}

void DxfDocument::rect(const std::string& layer, const Rect& r) { polygon(layer, rect_polygon(r)); }

void DxfDocument::circle(const std::string& layer, double cx, double cy, double d) {
  dxf_.writeCircle(*dw_, DL_CircleData(x(cx), y(cy), 0, length(d) / 2), on_layer(layer));
}

void DxfDocument::text(const std::string& layer, double at_x, double at_y, double height,
                       const std::string& text, bool centred) {
  // Centred text: horizontal 1 (centre), vertical 2 (middle) at the second alignment point.
  dxf_.writeText(*dw_,
                 DL_TextData(x(at_x), y(at_y), 0, x(at_x), y(at_y), 0, length(height), 1, 0,
                             centred ? 1 : 0, centred ? 2 : 0, dxf_text(text), "Standard", 0),
                 on_layer(layer));
}

void DxfDocument::close() {
  if (closed_) return;
  closed_ = true;
  dw_->sectionEnd();
  dw_->dxfEOF();
  if (!dw_->finish()) throw InputError("cannot write " + path_.string() + " (is the disk full?)");
}

}  // namespace curdle
