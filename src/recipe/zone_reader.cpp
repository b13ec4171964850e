// layout.outline = [[x, y], ...], and [[layout.zones]]: name, rect = [x, y, w, h] or
// polygon = [[x, y], ...] in millimetres, and rule = "exclude" or rule = "value" with value = N.
#include <fmt/format.h>

#include <cmath>

#include "curdle/text.h"
#include "layout/zone.h"
#include "recipe/layout_reader.h"

namespace curdle::reading {
namespace {

constexpr size_t kMostZones = 1000;
constexpr size_t kMostVertices = 10000;

// Every corner on the surface (zones are cut from it, so they must lie on it).
void check_on_surface(TableReader& r, const std::string& key, const Polygon& polygon,
                      const std::array<double, 2>& size) {
  for (const auto& p : polygon)
    if (p[0] < -1e-6 || p[1] < -1e-6 || p[0] > size[0] + 1e-6 || p[1] > size[1] + 1e-6)
      r.fail(key, fmt::format("has the corner [{:g}, {:g}] outside the surface of {:g} x {:g} mm; "
                              "zones and outlines lie on it, in mm from its bottom-left corner",
                              p[0], p[1], size[0], size[1]));
}

Polygon read_rect(TableReader& r) {
  const toml::array* a = r.get("rect")->as_array();
  std::array<double, 4> v{};
  bool ok = a && a->size() == 4;
  for (size_t k = 0; ok && k < 4; ++k) {
    const auto x = finite_number(a->get(k));
    ok = x && (k < 2 ? *x >= 0 : *x > 0);
    if (ok) v[k] = *x;
  }
  if (!ok) r.fail("rect", "must be [x, y, width, height] in millimetres, sizes above 0");
  return rect_polygon(Rect{v[0], v[1], v[2], v[3]});
}

Polygon read_polygon(TableReader& r, const std::string& key = "polygon") {
  const toml::array* a = r.get(key)->as_array();
  const std::string allowed =
      "must be at least 3 corners [[x, y], ...] in millimetres (at most 10000), a simple polygon "
      "whose edges do not cross";
  if (!a || a->size() < 3 || a->size() > kMostVertices) r.fail(key, allowed);
  Polygon polygon;
  for (const toml::node& item : *a) {
    const toml::array* p = item.as_array();
    const auto x = p && p->size() == 2 ? finite_number(p->get(0)) : std::nullopt;
    const auto y = p && p->size() == 2 ? finite_number(p->get(1)) : std::nullopt;
    if (!x || !y) r.fail(key, allowed);
    polygon.push_back({*x, *y});
  }
  if (polygon.front() == polygon.back()) polygon.pop_back();  // closed by repeating the first
  if (polygon.size() < 3 || !is_simple(polygon)) r.fail(key, allowed);
  return polygon;
}

Zone read_zone(TableReader& r, size_t values, const std::array<double, 2>& size) {
  Zone z;
  z.name = read_name(r, "name", "a name").value_or("");
  if (z.name.empty() || z.name.size() > 200)
    r.fail("name", "must be a name of 1 to 200 characters, such as \"planter\"");
  const bool rect = r.get("rect"), polygon = r.get("polygon");
  if (rect == polygon)
    r.fail(rect ? "polygon" : "name",
           "a zone needs either rect = [x, y, width, height] or polygon = [[x, y], ...] in mm, "
           "not both");
  z.polygon = rect ? read_rect(r) : read_polygon(r);
  check_on_surface(r, rect ? "rect" : "polygon", z.polygon, size);
  const std::string rule = read_string(r, "rule", "\"exclude\" or \"value\"").value_or("");
  if (rule == "exclude") {
    z.rule = ZoneRule::exclude;
    if (r.get("value"))
      r.fail("value", "is for rule = \"value\"; an excluded zone has no elements");
    // Edges along x and y cut as rectangles; sloping or curved ones as polygons (union.h).
    if (const auto rects = as_rectangles(z.polygon)) z.rects = *rects;
  } else if (rule == "value") {
    z.rule = ZoneRule::value;
    z.value = static_cast<uint32_t>(
        read_int(r, "value", 0, 0, static_cast<int64_t>(values) - 1, /*required=*/true));
  } else {
    r.fail("rule",
           "must be \"exclude\" (no elements: planters, drains, columns) or \"value\" with value = "
           "N (every element whose centre it holds takes value N)");
  }
  return z;
}

}  // namespace

void read_outline(TableReader& r, LayoutSpec& spec) {
  if (!r.get("outline")) return;
  Polygon outline = read_polygon(r, "outline");
  double x1 = 0, y1 = 0;
  for (const auto& p : outline) {
    if (p[0] < 0 || p[1] < 0)
      r.fail("outline", fmt::format("has the corner [{:g}, {:g}]: corners are in mm from the "
                                    "surface's origin, x and y from 0",
                                    p[0], p[1]));
    x1 = std::max(x1, p[0]), y1 = std::max(y1, p[1]);
  }
  if (x1 > 1e7 || y1 > 1e7) r.fail("outline", "must lie within 10 km of the origin");
  if (spec.size)
    check_on_surface(r, "outline", outline, *spec.size);
  else
    spec.size = std::array<double, 2>{x1, y1};
  spec.outline = std::move(outline);
}

void read_zones(TableReader& r, const Design& design, LayoutSpec& spec) {
  const toml::node* n = r.get("zones");
  if (!n) return;
  const toml::array* a = n->as_array();
  if (a && a->empty()) return;  // no zones (the page sends [] when all are removed)
  if (!a || !a->is_array_of_tables() || a->size() > kMostZones)
    r.fail("zones",
           "must be [[layout.zones]] tables (at most 1000), each with name, rect or "
           "polygon, and rule");
  if (!spec.size)
    r.fail("zones", "need the surface's size in mm (the layout's floor, wall or size key)");
  const size_t values = size_t{1} << design.curds.size();
  for (size_t i = 0; i < a->size(); ++i) {
    TableReader zr(*a->get(i)->as_table(), r.key_path("zones." + std::to_string(i)), r.source(),
                   {"name", "rect", "polygon", "rule", "value"});
    spec.zones.push_back(read_zone(zr, values, *spec.size));
  }
}

}  // namespace curdle::reading
