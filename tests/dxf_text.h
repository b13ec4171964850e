// DXF drawings written group by group for the site readers' tests: a header with $INSUNITS,
// blocks, and entities with handles and layers, as a CAD program exports them.
#pragma once

#include <fmt/format.h>

#include <array>
#include <string>
#include <vector>

namespace curdle::testing {

class DxfText {
 public:
  explicit DxfText(int insunits = 4) {
    group(0, "SECTION"), group(2, "HEADER"), group(9, "$INSUNITS"), group(70, insunits);
    group(0, "ENDSEC");
  }
  DxfText& begin_blocks() { return group(0, "SECTION"), group(2, "BLOCKS"); }
  DxfText& block(const std::string& name, double bx = 0, double by = 0) {
    group(0, "BLOCK"), group(8, "0"), group(2, name), group(70, 0);
    return group(10, bx), group(20, by), group(30, 0), group(3, name);
  }
  DxfText& end_block() { return group(0, "ENDBLK"), group(8, "0"); }
  DxfText& begin_entities() {
    return group(0, "ENDSEC"), group(0, "SECTION"), group(2, "ENTITIES");
  }
  DxfText& begin_entities_only() { return group(0, "SECTION"), group(2, "ENTITIES"); }
  // Each vertex {x, y, bulge}.
  DxfText& lwpolyline(const std::string& layer, const std::string& handle,
                      const std::vector<std::array<double, 3>>& vertices, bool closed,
                      double extrusion_z = 1, double width = 0) {
    group(0, "LWPOLYLINE"), group(5, handle), group(8, layer);
    group(90, static_cast<int>(vertices.size())), group(70, closed ? 1 : 0);
    if (width != 0) group(43, width);
    for (const auto& v : vertices) {
      group(10, v[0]), group(20, v[1]);
      if (v[2] != 0) group(42, v[2]);
    }
    if (extrusion_z != 1) group(210, 0.0), group(220, 0.0), group(230, extrusion_z);
    return *this;
  }
  DxfText& line(const std::string& layer, const std::string& handle, double x1, double y1,
                double x2, double y2, double z2 = 0) {
    group(0, "LINE"), group(5, handle), group(8, layer);
    return group(10, x1), group(20, y1), group(30, 0.0), group(11, x2), group(21, y2),
           group(31, z2);
  }
  DxfText& arc(const std::string& layer, const std::string& handle, double cx, double cy, double r,
               double from, double to) {
    group(0, "ARC"), group(5, handle), group(8, layer);
    return group(10, cx), group(20, cy), group(30, 0.0), group(40, r), group(50, from),
           group(51, to);
  }
  DxfText& circle(const std::string& layer, const std::string& handle, double cx, double cy,
                  double r) {
    group(0, "CIRCLE"), group(5, handle), group(8, layer);
    return group(10, cx), group(20, cy), group(30, 0.0), group(40, r);
  }
  DxfText& insert(const std::string& layer, const std::string& handle, const std::string& name,
                  double x, double y, double sx = 1, double sy = 1, double angle = 0,
                  double extrusion_z = 1) {
    group(0, "INSERT"), group(5, handle), group(8, layer), group(2, name);
    group(10, x), group(20, y), group(30, 0.0);
    if (sx != 1) group(41, sx);
    if (sy != 1) group(42, sy);
    if (angle != 0) group(50, angle);
    if (extrusion_z != 1) group(210, 0.0), group(220, 0.0), group(230, extrusion_z);
    return *this;
  }
  std::string text() const { return text_ + "0\nENDSEC\n0\nEOF\n"; }

 private:
  DxfText& group(int code, const std::string& value) {
    text_ += fmt::format("{}\n{}\n", code, value);
    return *this;
  }
  DxfText& group(int code, const char* value) { return group(code, std::string(value)); }
  DxfText& group(int code, int value) { return group(code, std::to_string(value)); }
  DxfText& group(int code, double value) { return group(code, fmt::format("{:.17g}", value)); }
  std::string text_;
};

}  // namespace curdle::testing
