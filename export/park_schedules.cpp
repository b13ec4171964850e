#include "export/park_schedules.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <tuple>

#include "export/csv_field.h"
#include "export/wkt.h"
#include "layout/piece.h"
#include "layout/zone.h"

namespace curdle {
namespace {

std::string zone_of(const Layout& layout, double x, double y) {
  for (const ZoneCount& z : layout.zones)
    if (contains(z.polygon, x, y)) return z.name;
  return "";
}

std::array<double, 2> centre(const Element& e) {
  if (e.circle) return {e.circle->cx, e.circle->cy};
  const Rect b = laid_bounds(e);
  return {b.x + b.w / 2, b.y + b.h / 2};
}

}  // namespace

void write_planting_csv(std::ostream& out, const Layout& layout) {
  out << kUtf8Mark << "element_id,plant,x_mm,y_mm,canopy_diameter_mm,value,zone\r\n";
  for (const Element& e : layout.elements) {
    if (!e.stands || !e.circle) continue;
    const auto [x, y] = centre(e);
    out << fmt::format("{},{},{},{},{},{},{}\r\n", e.id, csv_field(e.type), mm_text(x), mm_text(y),
                       mm_text(e.circle->d), e.value, csv_field(zone_of(layout, x, y)));
  }
}

void write_furniture_csv(std::ostream& out, const Layout& layout) {
  out << kUtf8Mark << "element_id,item,x_mm,y_mm,width_mm,depth_mm,value,zone\r\n";
  for (const Element& e : layout.elements) {
    if (!e.stands || e.circle) continue;
    const auto [x, y] = centre(e);
    const Rect b = laid_bounds(e);
    out << fmt::format("{},{},{},{},{},{},{},{}\r\n", e.id, csv_field(e.type), mm_text(x),
                       mm_text(y), mm_text(b.w), mm_text(b.h), e.value,
                       csv_field(zone_of(layout, x, y)));
  }
}

void write_surfaces_csv(std::ostream& out, const Layout& layout) {
  struct Line {
    double area = 0;  // mm², each piece's to the mm² as schedule.csv gives it
    uint64_t pieces = 0, cut = 0;
  };
  std::map<std::pair<std::string, std::string>, Line> lines;  // material, zone
  for (const Element& e : layout.elements) {
    if (e.stands) continue;
    const auto [x, y] = centre(e);
    Line& l = lines[{piece_material(layout, e), zone_of(layout, x, y)}];
    l.area += std::round(e.area());
    l.pieces += 1;
    l.cut += e.cut ? 1 : 0;
  }
  out << kUtf8Mark << "material,zone,area_m2,pieces,cut\r\n";
  for (const auto& [key, l] : lines)
    out << fmt::format("{},{},{:.6f},{},{}\r\n", csv_field(key.first), csv_field(key.second),
                       l.area / 1e6, l.pieces, l.cut);
}

}  // namespace curdle
