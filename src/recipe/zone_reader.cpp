// layout.outline = [[x, y], ...], and [[layout.zones]]: name, rect = [x, y, w, h] or
// polygon = [[x, y], ...] in millimetres, and rule = "exclude" or rule = "value" with value = N
// or the curds' names ("tree+bench").
// A vertex [x, y, bulge] makes the edge to the next an arc (contour.h).
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "curdle/overlay.h"
#include "curdle/text.h"
#include "layout/contour.h"
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

// A value rule's value: a number, or what the curds place in it by name ("tree", "tree+bench"),
// as the legend names the values.
uint32_t read_zone_value(TableReader& r, const std::vector<std::string>& labels) {
  const toml::node* n = r.get("value");
  if (n && n->is_string()) {
    const std::string name = n->as_string()->get();
    for (uint32_t v = 0; v < labels.size(); ++v)
      if (labels[v] == name) return v;
    std::string curds;  // each curd alone: value 1, 2, 4, ...
    for (size_t v = 1; v < labels.size(); v <<= 1)
      curds += (v > 1 ? ", \"" : "\"") + labels[v] + "\"";
    r.fail("value", "must be a value 0 to " + std::to_string(labels.size() - 1) +
                        " or the curds it holds by name, joined with \"+\" as the legend names "
                        "them (" +
                        labels.back() + "): " + curds);
  }
  return static_cast<uint32_t>(
      read_int(r, "value", 0, 0, static_cast<int64_t>(labels.size()) - 1, /*required=*/true));
}

Zone read_zone(TableReader& r, const std::vector<std::string>& labels,
               const std::array<double, 2>& size, double tolerance) {
  Zone z;
  z.name = read_name(r, "name", "a name").value_or("");
  if (z.name.empty() || z.name.size() > 200)
    r.fail("name", "must be a name of 1 to 200 characters, such as \"planter\"");
  const bool rect = r.get("rect"), polygon = r.get("polygon");
  if (rect == polygon)
    r.fail(rect ? "polygon" : "name",
           "a zone needs either rect = [x, y, width, height] or polygon = [[x, y], ...] in mm, "
           "not both");
  if (rect) {
    z.polygon = read_rect(r);
  } else {
    ReadContour c = read_contour(r, "polygon", tolerance);
    z.polygon = std::move(c.polygon);
    z.contour = std::move(c.contour);
  }
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
    z.value = read_zone_value(r, labels);
  } else {
    r.fail("rule",
           "must be \"exclude\" (no elements: planters, drains, columns) or \"value\" with value = "
           "N or the curds by name, e.g. \"tree\" (every element whose centre it holds takes "
           "that value)");
  }
  return z;
}

// An arc given by its centre, from the vertex before it: { centre = [x, y], sweep = degrees }
// or { centre = [x, y], length = mm along it }, positive anticlockwise, and `radius` if given
// as a check. Sets `from`'s bulge and returns the arc's end, the next vertex.
ContourVertex read_arc_to(TableReader& r, const std::string& key, const toml::table& t,
                          ContourVertex& from, double reach) {
  const std::string allowed =
      "an arc by its centre follows the vertex it starts from: { centre = [x, y], sweep = "
      "degrees } or { centre = [x, y], length = mm along the arc }, positive anticlockwise, "
      "under a whole turn; radius = mm as a check of the distance from that vertex to the centre";
  for (const auto& [name, value] : t)
    if (name != "centre" && name != "sweep" && name != "length" && name != "radius")
      r.fail(key, fmt::format("has an arc with the key '{}': {}", name.str(), allowed));
  const toml::array* c = t.get("centre") ? t.get("centre")->as_array() : nullptr;
  const auto cx = c && c->size() == 2 ? finite_number(c->get(0)) : std::nullopt;
  const auto cy = c && c->size() == 2 ? finite_number(c->get(1)) : std::nullopt;
  const auto sweep = finite_number(t.get("sweep")), length = finite_number(t.get("length"));
  if (!cx || !cy || std::fabs(*cx) > reach || std::fabs(*cy) > reach ||
      (t.get("sweep") != nullptr) == (t.get("length") != nullptr) || (t.get("sweep") && !sweep) ||
      (t.get("length") && !length))
    r.fail(key, allowed);
  const double radius = std::hypot(from.x - *cx, from.y - *cy);
  if (radius < 1) r.fail(key, "has an arc whose centre is its start: " + allowed);
  if (t.get("radius")) {
    const auto given = finite_number(t.get("radius"));
    if (!given || std::fabs(*given - radius) > 0.5)
      r.fail(key, fmt::format("has an arc of radius {} round [{:g}, {:g}], but its start [{:g}, "
                              "{:g}] lies {:.1f} mm from that centre",
                              given ? fmt::format("{:g}", *given) : std::string("(not a number)"),
                              *cx, *cy, from.x, from.y, radius));
  }
  const double turn = sweep ? *sweep * std::numbers::pi / 180 : *length / radius;
  if (std::fabs(turn) < 1e-9 || std::fabs(turn) > 359 * std::numbers::pi / 180)
    r.fail(key, fmt::format("has an arc of {:.2f}° round [{:g}, {:g}]: {}",
                            turn * 180 / std::numbers::pi, *cx, *cy, allowed));
  const double start = std::atan2(from.y - *cy, from.x - *cx);
  from.bulge = bulge_of_sweep(turn);
  const ContourVertex to{*cx + radius * std::cos(start + turn),
                         *cy + radius * std::sin(start + turn), 0};
  if (std::fabs(to.x) > reach || std::fabs(to.y) > reach)
    r.fail(key, fmt::format("has an arc round [{:g}, {:g}] that ends at [{:.0f}, {:.0f}], beyond "
                            "{:g} mm of the origin",
                            *cx, *cy, to.x, to.y, reach));
  return to;
}

}  // namespace

Contour read_vertices(TableReader& r, const std::string& key, const std::string& allowed,
                      size_t least, size_t most, double reach) {
  const toml::array* a = r.get(key)->as_array();
  if (!a || a->size() < least || a->size() > most) r.fail(key, allowed);
  Contour contour;
  // Every corner's third number the same and over 1 (each edge an arc past a half turn): points
  // copied from a 3-D model, [x, y, z], not bulges.
  std::optional<double> third;
  bool thirds_alike = true, bulge_beyond = false;
  for (const toml::node& item : *a) {
    if (const toml::table* arc = item.as_table()) {
      if (contour.empty())
        r.fail(key,
               "starts with an arc: its first item is the vertex [x, y] an arc by its centre "
               "{ centre = [x, y], sweep = degrees } starts from");
      contour.push_back(read_arc_to(r, key, *arc, contour.back(), reach));
      continue;
    }
    const toml::array* p = item.as_array();
    const bool sized = p && (p->size() == 2 || p->size() == 3);
    const auto x = sized ? finite_number(p->get(0)) : std::nullopt;
    const auto y = sized ? finite_number(p->get(1)) : std::nullopt;
    const auto bulge = sized && p->size() == 3 ? finite_number(p->get(2)) : std::optional(0.0);
    thirds_alike = thirds_alike && sized && p->size() == 3 && bulge && (!third || *third == *bulge);
    if (bulge) third = *bulge;
    if (!x || !y || !bulge || std::fabs(*x) > reach || std::fabs(*y) > reach) r.fail(key, allowed);
    bulge_beyond = bulge_beyond || std::fabs(*bulge) > 1000;
    contour.push_back({*x, *y, tidy_bulge(*bulge)});
  }
  // A closing arc given by its centre ends on the first vertex, to rounding: the same vertex.
  if (contour.size() > 2 && std::hypot(contour.back().x - contour.front().x,
                                       contour.back().y - contour.front().y) < 0.01) {
    contour.back().x = contour.front().x;
    contour.back().y = contour.front().y;
  }
  const bool three_d = thirds_alike && third && std::fabs(*third) > 1 && contour.size() >= 3;
  if (bulge_beyond && !three_d) r.fail(key, allowed);
  if (three_d)
    r.fail(key, fmt::format("reads as 3-D points [x, y, z], every third number {:g}: a plan's "
                            "corners are [x, y] in millimetres (a third number is a bulge, which "
                            "makes the edge to the next corner an arc)",
                            *third));
  return contour;
}

// A polygon's corners, each [x, y] or [x, y, bulge]: the contour with its arcs, and its polygon
// with the arcs as chords within the layout's chord tolerance.
ReadContour read_contour(TableReader& r, const std::string& key, double tolerance) {
  const std::string allowed =
      "must be at least 3 corners [[x, y], ...] in millimetres (at most 10000), a simple polygon "
      "whose edges do not cross; [x, y, bulge] makes the edge to the next corner an arc (bulge "
      "= tan(angle / 4), positive counter-clockwise, as CAD's polylines; at most 1000 in size), "
      "or an arc after a corner by its centre, { centre = [x, y], sweep = degrees } or { centre "
      "= [x, y], length = mm }";
  Contour contour = read_vertices(r, key, allowed, 2, kMostVertices, 1e300);
  if (contour.size() > 2 && contour.front().x == contour.back().x &&
      contour.front().y == contour.back().y)
    contour.pop_back();  // closed by repeating the first
  // Before its arcs are drawn in chords: an arc swept kilometres wide would take millions.
  const Rect extent = contour_bounds(contour);
  if (!(extent.x >= -1e7 && extent.y >= -1e7 && extent.right() <= 1e7 && extent.top() <= 1e7))
    r.fail(key, fmt::format("reaches [{:g}, {:g}] to [{:g}, {:g}] with its corners and arcs, "
                            "beyond 10 km from the origin: a surface and its zones lie within it",
                            extent.x, extent.y, extent.right(), extent.top()));
  ReadContour read{contour, flatten(contour, tolerance)};
  if (read.polygon.size() < 3 || !is_simple(read.polygon)) r.fail(key, allowed);
  if (!has_arcs(read.contour)) read.contour.clear();
  return read;
}

void read_outline(TableReader& r, LayoutSpec& spec) {
  if (!r.get("outline")) return;
  ReadContour outline = read_contour(r, "outline", spec.chord_tolerance);
  // An arc can swell past its corners: the true extent bounds the surface.
  const Rect bounds =
      contour_bounds(outline.contour.empty() ? contour_of(outline.polygon) : outline.contour);
  if (bounds.x < -1e-9 || bounds.y < -1e-9)
    r.fail("outline", fmt::format("reaches [{:g}, {:g}]: corners and arcs are in mm from the "
                                  "surface's origin, x and y from 0",
                                  bounds.x, bounds.y));
  if (bounds.right() > 1e7 || bounds.top() > 1e7)
    r.fail("outline", "must lie within 10 km of the origin");
  if (spec.size)
    check_on_surface(r, "outline", outline.polygon, *spec.size);
  else
    spec.size = std::array<double, 2>{bounds.right(), bounds.top()};
  spec.outline = std::move(outline.polygon);
  spec.outline_contour = std::move(outline.contour);
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
  std::vector<std::string> labels(size_t{1} << design.curds.size());
  for (uint32_t v = 0; v < labels.size(); ++v) labels[v] = value_label(v, design.curds);
  for (size_t i = 0; i < a->size(); ++i) {
    TableReader zr(*a->get(i)->as_table(), r.key_path("zones." + std::to_string(i)), r.source(),
                   {"name", "rect", "polygon", "rule", "value"});
    spec.zones.push_back(read_zone(zr, labels, *spec.size, spec.chord_tolerance));
  }
}

}  // namespace curdle::reading
