#include "layout/arc_setting_out.h"

#include <fmt/format.h>

#include <cmath>

#include "layout/drawing_sheet.h"

namespace curdle {
namespace {

std::string point(const std::array<double, 2>& p) {
  return fmt::format("({}, {})", drawing_mm(p[0]), drawing_mm(p[1]));
}

void add_contour(const Contour& c, const std::string& prefix, bool zone,
                 std::vector<SetOutArc>& out) {
  if (c.size() == 2 && c[0].bulge != 0 && c[1].bulge != 0) {
    const Arc a = arc_between(c[0], c[1]), b = arc_between(c[1], c[0]);
    if (std::hypot(a.centre[0] - b.centre[0], a.centre[1] - b.centre[1]) < 1e-6 &&
        std::fabs(a.radius - b.radius) < 1e-6) {
      SetOutArc s{prefix, a, true, ""};
      s.line = fmt::format("{}: circle, centre {}, radius {}", prefix, point(a.centre),
                           drawing_mm(a.radius));
      out.push_back(std::move(s));
      return;
    }
  }
  size_t number = 0;
  for (size_t i = 0; i < c.size(); ++i) {
    if (c[i].bulge == 0) continue;
    SetOutArc s;
    s.arc = arc_between(c[i], c[(i + 1) % c.size()]);
    s.name = zone ? fmt::format("{} A{}", prefix, ++number) : fmt::format("A{}", ++number);
    s.line =
        fmt::format("{}: arc, centre {}, radius {}, from {} to {}", s.name, point(s.arc.centre),
                    drawing_mm(s.arc.radius), point(s.arc.from), point(s.arc.to));
    out.push_back(std::move(s));
  }
}

}  // namespace

std::vector<SetOutArc> arcs_to_set_out(const Layout& layout) {
  std::vector<SetOutArc> out;
  add_contour(layout.outline_contour, "outline", false, out);
  for (const ZoneCount& z : layout.zones) add_contour(z.contour, z.name, true, out);
  return out;
}

std::vector<std::array<double, 2>> set_out_points(const Contour& contour, double width,
                                                  double height) {
  std::vector<std::array<double, 2>> points;
  for (size_t i = 0; i < contour.size(); ++i) {
    points.push_back({contour[i].x, contour[i].y});
    if (contour[i].bulge == 0) continue;
    const Arc a = arc_between(contour[i], contour[(i + 1) % contour.size()]);
    if (a.centre[0] >= 0 && a.centre[1] >= 0 && a.centre[0] <= width && a.centre[1] <= height)
      points.push_back(a.centre);
  }
  return points;
}

}  // namespace curdle
