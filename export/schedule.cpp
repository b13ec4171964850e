#include "export/schedule.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "curdle/palette.h"
#include "export/csv_field.h"

namespace curdle {
namespace {

std::string mm(double v) { return fmt::format("{:.1f}", v); }

const Rgb& colour_of(const Layout& layout, const Element& e) {
  return e.type.empty() ? layout.legend[e.value].colour : e.colour;
}

std::string type_of(const Layout& layout, const Element& e) {
  return e.type.empty() ? layout.element_type : e.type;
}

}  // namespace

int64_t lot_of(const Element& e, size_t index, const LayoutSpec& spec) {
  if (spec.lot_rows > 0) return e.row / spec.lot_rows + 1;
  if (spec.lot_size > 0) return static_cast<int64_t>(index) / spec.lot_size + 1;
  return 1;
}

void write_schedule_csv(std::ostream& out, const Layout& layout) {
  const Provenance& design = layout.source;
  const LayoutSpec& spec = layout.spec;
  std::string header = "element_id,lot,row,column,x_mm,y_mm,z_mm,width_mm,height_mm,value";
  for (const CurdSpec& c : design.curds) {
    header += ',';
    header += csv_field(c.name);
  }
  header +=
      ",element_type,colour,material,cut,cut_width_mm,cut_height_mm,opening_x_mm,"
      "opening_y_mm,opening_diameter_mm\r\n";
  out << header;
  std::string buffer;
  buffer.reserve(1 << 20);
  for (size_t i = 0; i < layout.elements.size(); ++i) {
    const Element& e = layout.elements[i];
    // The laid extent: the pieces' bounding box (the nominal size when whole).
    double x0 = e.nominal.x, y0 = e.nominal.y, x1 = e.nominal.right(), y1 = e.nominal.top();
    if (!e.shape.empty()) {
      x0 = y0 = 1e300, x1 = y1 = -1e300;
      for (const Rect& r : e.shape)
        x0 = std::min(x0, r.x), y0 = std::min(y0, r.y), x1 = std::max(x1, r.right()),
        y1 = std::max(y1, r.top());
    }
    const double z = layout.kind == LayoutKind::blocks
                         ? (e.cell_z - layout.view.origin[2]) * spec.blocks().voxel_h
                         : 0;
    // Openings of a perforated sheet are lotted by the fabrication sheet they are cut in.
    const std::string lot = e.sheet >= 0 ? layout.sheets[static_cast<size_t>(e.sheet)].id
                                         : std::to_string(lot_of(e, i, spec));
    fmt::format_to(std::back_inserter(buffer), "{},{},{},{},{},{},{},{},{},{}", e.id, lot, e.row,
                   e.column, mm(e.nominal.x), mm(e.nominal.y), mm(z), mm(e.nominal.w),
                   mm(e.nominal.h), e.value);
    for (size_t c = 0; c < design.curds.size(); ++c) buffer += (e.value >> c & 1) ? ",1" : ",0";
    fmt::format_to(std::back_inserter(buffer), ",{},{},{},{}", csv_field(type_of(layout, e)),
                   hex_colour(colour_of(layout, e)),
                   csv_field(e.type.empty() ? layout.legend[e.value].label : e.type), e.cut ? 1 : 0);
    if (e.cut)
      fmt::format_to(std::back_inserter(buffer), ",{},{}", mm(x1 - x0), mm(y1 - y0));
    else
      buffer += ",,";
    if (e.circle)
      fmt::format_to(std::back_inserter(buffer), ",{},{},{}", mm(e.circle->cx), mm(e.circle->cy),
                     mm(e.circle->d));
    else if (e.outline)
      fmt::format_to(std::back_inserter(buffer), ",{},{},", mm((x0 + x1) / 2), mm((y0 + y1) / 2));
    else
      buffer += ",,,";
    buffer += "\r\n";
    if (buffer.size() > (1 << 20) - 1024) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  }
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

void write_quantities_csv(std::ostream& out, const Layout& layout) {
  const LayoutSpec& spec = layout.spec;
  // One line per element type and colour: values that share a colour are one order.
  struct Line {
    uint64_t count = 0;
    double area = 0;
    std::map<uint32_t, std::string> values;  // value -> label
  };
  std::map<std::pair<std::string, std::string>, Line> lines;
  for (const Element& e : layout.elements) {
    Line& l = lines[{type_of(layout, e), hex_colour(colour_of(layout, e))}];
    ++l.count;
    l.area += e.area();
    l.values[e.value] = e.type.empty() ? layout.legend[e.value].label : e.type;
  }
  out << "element_type,colour,values,labels,count,area_m2,spare,count_with_spare,pack_size,"
         "packs\r\n";
  for (const auto& [key, l] : lines) {
    std::string values, labels;
    for (const auto& [v, label] : l.values) {
      if (!values.empty()) values += ' ', labels += "; ";
      values += std::to_string(v);
      labels += label;
    }
    const auto with_spare = static_cast<uint64_t>(std::ceil(l.count * (1 + spec.spare) - 1e-9));
    const auto packs = (with_spare + spec.pack - 1) / spec.pack;
    out << fmt::format("{},{},{},{},{},{:.4f},{},{},{},{}\r\n", csv_field(key.first), key.second,
                       values, csv_field(labels), l.count, l.area / 1e6, spec.spare, with_spare,
                       spec.pack, packs);
  }
}

}  // namespace curdle
