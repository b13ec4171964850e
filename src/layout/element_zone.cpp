#include "layout/element_zone.h"

#include "layout/piece.h"
#include "layout/union.h"
#include "layout/zone.h"

namespace curdle {

std::string zone_at(const Layout& layout, double x, double y) {
  for (const ZoneCount& z : layout.zones)
    if (contains(z.polygon, x, y)) return z.name;
  return "";
}

std::string zone_of_element(const Layout& layout, const Element& e) {
  if (e.stands) {
    if (e.circle) return zone_at(layout, e.circle->cx, e.circle->cy);
    const Rect b = laid_bounds(e);
    return zone_at(layout, b.x + b.w / 2, b.y + b.h / 2);
  }
  const Rect b = laid_bounds(e);
  std::vector<Outline> piece = piece_outlines(e);
  if (piece.empty()) piece.push_back({{rect_polygon(b)}, b.area()});
  const double whole = e.area();
  double best = 0, inside = 0;
  std::string name;
  for (const ZoneCount& z : layout.zones) {
    const size_t n = z.polygon.size();
    bool crosses = false;  // else the piece's box lies wholly in the zone or wholly out
    for (size_t i = 0; i < n && !crosses; ++i)
      crosses = segment_meets(z.polygon[i], z.polygon[(i + 1) % n], b);
    const double share = crosses ? area_inside(piece, z.polygon)
                         : contains(z.polygon, b.x + b.w / 2, b.y + b.h / 2) ? whole
                                                                             : 0.0;
    inside += share;
    if (share > best) best = share, name = z.name;
  }
  return best > whole - inside ? name : "";
}

}  // namespace curdle
