#include "export/schedules/park_schedules.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <tuple>

#include "io/csv_field.h"
#include "layout/edging.h"
#include "layout/element_zone.h"
#include "layout/piece.h"
#include "layout/wkt.h"
#include "layout/zone.h"

namespace curdle {
namespace {

std::array<double, 2> centre(const Element& e) {
  if (e.circle) return {e.circle->cx, e.circle->cy};
  const Rect b = laid_bounds(e);
  return {b.x + b.w / 2, b.y + b.h / 2};
}

// A size the recipe gave, or an empty cell.
std::string given(double mm) { return mm > 0 ? mm_text(mm) : ""; }

}  // namespace

void write_planting_csv(std::ostream& out, const Layout& layout) {
  out << kUtf8Mark
      << "element_id,plant,species,centre_x_mm,centre_y_mm,canopy_diameter_mm,girth_cm,"
         "root_ball_mm,pit_width_mm,pit_length_mm,value,zone\r\n";
  for (const Element& e : layout.elements) {
    if (!e.stands || !e.circle) continue;
    const auto [x, y] = centre(e);
    const PlantingSpec& p = planting_of(layout, e);
    out << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\r\n", e.id, csv_field(e.type),
                       csv_field(p.species), mm_text(x), mm_text(y), mm_text(e.circle->d),
                       p.girth_text(), given(p.root_ball), given(p.pit[0]), given(p.pit[1]),
                       e.value, csv_field(zone_of_element(layout, e)));
  }
}

void write_furniture_csv(std::ostream& out, const Layout& layout) {
  out << kUtf8Mark
      << "element_id,item,product,centre_x_mm,centre_y_mm,width_mm,depth_mm,long_side_deg,"
         "facing_deg,value,zone\r\n";
  for (const Element& e : layout.elements) {
    if (!e.stands || e.circle) continue;
    const auto [x, y] = centre(e);
    const Rect b = laid_bounds(e);
    const int long_side = b.w >= b.h ? 0 : 90;  // objects stand square to the grid
    // The way a seated person looks, degrees clockwise from the drawing's north (+y).
    const int facing = static_cast<int>(e.turn);
    out << fmt::format("{},{},{},{},{},{},{},{},{},{},{}\r\n", e.id, csv_field(e.type),
                       csv_field(planting_of(layout, e).species), mm_text(x), mm_text(y),
                       mm_text(b.w), mm_text(b.h), long_side, facing, e.value,
                       csv_field(zone_of_element(layout, e)));
  }
}

void write_surfaces_csv(std::ostream& out, const Layout& layout) {
  struct Line {
    double area = 0;  // mm², each piece's to the mm² as schedule.csv gives it
    uint64_t pieces = 0, cut = 0;
    double edging = 0;  // mm
  };
  std::map<std::pair<std::string, std::string>, Line> lines;  // material, zone
  std::map<std::string, uint32_t> material_group;
  std::vector<EdgedPiece> pieces;
  std::vector<Line*> line_of;
  for (const Element& e : layout.elements) {
    if (e.stands) continue;
    const std::string& material = piece_material(layout, e);
    Line& l = lines[{material, zone_of_element(layout, e)}];
    l.area += std::round(e.area());
    l.pieces += 1;
    l.cut += e.cut ? 1 : 0;
    const auto group = material_group.try_emplace(material, material_group.size()).first->second;
    pieces.push_back({piece_rings(e), group});
    line_of.push_back(&l);
  }
  const std::vector<double> edging = unshared_edge_lengths(pieces);
  for (size_t i = 0; i < pieces.size(); ++i) line_of[i]->edging += edging[i];
  out << kUtf8Mark << "material,zone,area_m2,pieces,cut,edging_m\r\n";
  for (const auto& [key, l] : lines)
    out << fmt::format("{},{},{:.6f},{},{},{:.3f}\r\n", csv_field(key.first), csv_field(key.second),
                       l.area / 1e6, l.pieces, l.cut, l.edging / 1e3);
}

}  // namespace curdle
