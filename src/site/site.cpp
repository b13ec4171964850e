// From the drawing's layers to the surface: open pieces (LINE and ARC chains, open polylines)
// joined end to end, the units and the datum applied, and everything checked before any piece
// is laid.
#include "site/site.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <unordered_map>

#include "curdle/stop.h"
#include "layout/zone.h"
#include "site/dxf_reader.h"
#include "site/gltf_reader.h"
#include "site/layer_shapes.h"
#include "site/svg_reader.h"

namespace curdle::site {
namespace {

// Coordinates in mm are kept to the nanometre, so that the same drawing in other units gives
// the same numbers (14,000 mm drawn as 551.1811... in gives 14000.000000000002 before this).
double snapped(double mm) {
  const double v = std::round(mm * 1e6) / 1e6;
  return v == 0 ? 0 : v;  // no -0
}

// The checks a recipe's own polygon passes, before any geometry is cut along a drawn one: at
// least three corners, edges that do not cross or touch, and an area of a square millimetre at
// least (a sliver 1e-7 mm wide, or corners that meet once in mm, is none).
constexpr double kLeastArea = 1;  // mm²

void check_simple(const Polygon& mm, const Closed& c, const std::string& layer, const char* role,
                  const std::string& file, int precision) {
  const double area = mm.size() < 3 ? 0 : polygon_area(mm);
  if (!(area >= kLeastArea))
    throw InputError(fmt::format(
        "{}: the {} {} on layer \"{}\" (at {} in the drawing) encloses {} mm², less than the "
        "{:g} mm² a {} needs: it is a line or a sliver; redraw it as a closed shape, or take it "
        "off the layer",
        file, role, c.handles, layer, point_text(c.path.front(), precision),
        fmt::format("{:.3g}", area), kLeastArea, role));
  if (const auto crossing = first_crossing(mm))
    throw InputError(fmt::format(
        "{}: the {} {} on layer \"{}\" crosses or touches itself at ({:g}, {:g}) mm from the "
        "layout's datum; a {} goes round its area once: redraw it",
        file, role, c.handles, layer, (*crossing)[0], (*crossing)[1], role));
}

Contour counter_clockwise(Contour c) {
  double twice = 0;
  for (size_t i = 0; i < c.size(); ++i) {
    const ContourVertex& a = c[i];
    const ContourVertex& b = c[(i + 1) % c.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  // Two-vertex contours (a circle) have no shoelace area: their bulges say the turn.
  const bool clockwise = c.size() == 2 ? c[0].bulge < 0 : twice < 0;
  if (!clockwise) return c;
  c.push_back(c.front());
  c = reversed(c);
  c.pop_back();
  return c;
}

std::string layers_with_shapes(const std::vector<std::string>& layers) {
  std::string names;
  for (size_t i = 0; i < layers.size() && i < 40; ++i)
    names += (i ? ", " : "") + ("\"" + layers[i] + "\"");
  if (layers.size() > 40) names += ", ...";
  return names.empty() ? "none" : names;
}

void check_named(const Drawing& drawing, const std::vector<std::string>& layers,
                 const std::string& layer, const std::string& file, const std::string& role) {
  if (std::any_of(drawing.shapes.begin(), drawing.shapes.end(),
                  [&](const Shape& s) { return on_layer(s, layer); }))
    return;
  throw InputError(
      fmt::format("{}: layer \"{}\" ({}) has nothing on it; the layers with shapes "
                  "are {}",
                  file, layer, role, layers_with_shapes(layers)));
}

}  // namespace

Drawing read_drawing(std::string_view bytes, const std::string& name, double chord_tolerance_mm,
                     double unit_mm) {
  std::string ending = name.size() >= 4 ? name.substr(name.size() - 4) : name;
  for (char& c : ending) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ending == ".glb" || ending == "gltf") return read_gltf(bytes, name);
  return ending == ".svg" ? read_svg(bytes, name, {chord_tolerance_mm, unit_mm})
                          : read_dxf(bytes, name, {chord_tolerance_mm, unit_mm});
}

double unit_mm(const std::string& name) {
  static const std::map<std::string, double> kUnits = {{"mm", 1},   {"cm", 10},   {"dm", 100},
                                                       {"m", 1000}, {"in", 25.4}, {"ft", 304.8}};
  const auto it = kUnits.find(name);
  return it == kUnits.end() ? 0 : it->second;
}

namespace {

// The units: the recipe's, else the drawing's; a unitless drawing must be told.
double units_of(const Drawing& drawing, const LayerMap& map, std::string& name,
                std::vector<std::string>& notes) {
  if (map.unit_mm > 0) {
    name = map.unit_name;
    if (drawing.unit_mm > 0 && drawing.unit_mm != map.unit_mm)
      notes.push_back(
          fmt::format("{} says its units are {}; read in {} as [layout.site] units "
                      "says",
                      map.file, drawing.unit_name, map.unit_name));
    return map.unit_mm;
  }
  if (drawing.unit_mm > 0) {
    name = drawing.unit_name;
    return drawing.unit_mm;
  }
  throw InputError(fmt::format(
      "{}: does not say its units ({}); say what they are with [layout.site] units = \"mm\", "
      "\"cm\", \"m\", \"in\" or \"ft\" (a drawing in metres read as millimetres would be laid "
      "1000 times too small)",
      map.file,
      drawing.unit_name.empty() ? "$INSUNITS is 0, unitless"
                                : drawing.unit_name + ", not a length curdle lays"));
}

// The datum in drawing units: as the recipe says, or the drawing's origin where the outline
// lies in its first quadrant, or else the outline's bottom-left corner.
std::array<double, 2> datum_of(const LayerMap& map, const Rect& bounds, double unit_mm,
                               double tolerance) {
  if (map.origin) return *map.origin;
  const bool first_quadrant = bounds.x >= -tolerance && bounds.y >= -tolerance &&
                              bounds.right() * unit_mm <= 1e7 && bounds.top() * unit_mm <= 1e7;
  if (!map.origin_at_outline && first_quadrant) return {0, 0};
  return {bounds.x, bounds.y};
}

Contour to_mm(const Contour& c, const std::array<double, 2>& datum, double unit_mm) {
  Contour out = c;
  for (ContourVertex& v : out)
    v = {snapped((v.x - datum[0]) * unit_mm), snapped((v.y - datum[1]) * unit_mm), v.bulge};
  return out;
}

void check_plausible(const Rect& mm, const LayerMap& map, const std::string& unit_name,
                     double unit_mm) {
  const double longer = std::max(mm.w, mm.h), shorter = std::min(mm.w, mm.h);
  if (longer <= 5e6 && shorter >= 10) return;
  const std::string size = fmt::format("{} x {} mm", grouped(mm.w), grouped(mm.h));
  const std::string hint =
      longer > 5e6 ? (unit_mm >= 1000 ? "is it drawn in millimetres? then units = \"mm\""
                                      : "is it drawn in other units? then say so with units")
                   : (unit_mm <= 1 ? "is it drawn in metres? then units = \"m\""
                                   : "is it drawn in other units? then say so with units");
  throw InputError(
      fmt::format("{}: the outline is {} read in {} ({}), which is no surface curdle "
                  "lays (at most 5 km, at least 10 mm across); {} in [layout.site]",
                  map.file, size, unit_name, longer > 5e6 ? "too large" : "too small", hint));
}

// The openings and zones: inside the outline, each named after its layer.
void read_holes(const Drawing& drawing, const LayerMap& map, const Polygon& outline,
                const std::array<double, 2>& datum, double unit_mm, double join_tolerance,
                Site& site) {
  auto place = [&](const Closed& c, const std::string& layer, const char* role) {
    Contour mm = counter_clockwise(to_mm(c.path, datum, unit_mm));
    const Polygon p = flatten(mm, map.chord_tolerance);
    check_simple(p, c, layer, role, map.file, drawing.precision);
    const bool any_inside = std::any_of(
        p.begin(), p.end(), [&](const auto& v) { return contains(outline, v[0], v[1]); });
    const bool holds_outline = !outline.empty() && contains(p, outline[0][0], outline[0][1]);
    if (!any_inside && !holds_outline)
      throw InputError(fmt::format(
          "{}: the {} {} on layer \"{}\" lies outside the outline (at "
          "{} in the drawing); move it onto the surface, or off the layer",
          map.file, role, c.handles, layer, point_text(c.path.front(), drawing.precision)));
    return mm;
  };
  for (const std::string& layer : map.openings) {
    PassedOver passed;
    // A window block's frame and sashes lie inside its outer line: the opening is the outer one.
    for (const Closed& c :
         closed_on(drawing, layer, join_tolerance, map.file, "opening", unit_mm, passed))
      site.openings.push_back(place(c, layer, "opening"));
    note_passed_over(passed, layer, site.notes);
  }
  for (const ZoneLayer& z : map.zones) {
    PassedOver passed;
    std::vector<Closed> found =
        closed_on(drawing, z.layer, join_tolerance, map.file, "zone", unit_mm, passed);
    if (z.around)
      found = {
          smallest_around(found, *z.around, join_tolerance, map.file, z.layer, drawing.precision)};
    note_passed_over(passed, z.layer, site.notes);
    for (size_t i = 0; i < found.size(); ++i)
      site.zones.push_back({found.size() > 1 ? fmt::format("{} {}", z.layer, i + 1) : z.layer,
                            z.rule, z.value, place(found[i], z.layer, "zone")});
  }
}

// The outline among the layer's shapes: the one there is, or the one the recipe picks by a
// point inside it (the smallest shape around it, as CAD's BOUNDARY picks), by an entity's
// handle, or the largest.
Closed picked_outline(const std::vector<Closed>& outlines, const LayerMap& map,
                      const Drawing& drawing, double tolerance) {
  auto list = [&]() {
    std::string text;
    for (size_t i = 0; i < outlines.size() && i < 12; ++i) {
      const Rect b = contour_bounds(outlines[i].path);
      text += fmt::format("{}{} ({} x {} at {})", i ? "; " : "", outlines[i].handles,
                          number_text(b.w, drawing.precision), number_text(b.h, drawing.precision),
                          point_text({b.x, b.y, 0}, drawing.precision));
    }
    return outlines.size() > 12 ? text + "; ..." : text;
  };
  if (map.pick.around) {
    try {
      return smallest_around(outlines, *map.pick.around, tolerance, map.file, map.outline,
                             drawing.precision);
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + "; the layer's shapes are " +
                       (outlines.empty() ? std::string("none") : list()));
    }
  }
  if (!map.pick.handle.empty()) {
    for (const Closed& c : outlines)
      for (const Shape* s : c.shapes)
        if (s->handle == map.pick.handle || s->insert_handle == map.pick.handle) return c;
    throw InputError(fmt::format(
        "{}: no closed shape on layer \"{}\" is drawn by the entity "
        "with handle {}; the layer's shapes are {}",
        map.file, map.outline, map.pick.handle, outlines.empty() ? std::string("none") : list()));
  }
  if (map.pick.largest && !outlines.empty()) {
    size_t best = 0;
    for (size_t i = 1; i < outlines.size(); ++i)
      if (contour_area(outlines[i].path) > contour_area(outlines[best].path)) best = i;
    return outlines[best];
  }
  if (outlines.empty())
    throw InputError(
        fmt::format("{}: layer \"{}\" holds no closed shape to be the outline; draw "
                    "the surface's outline on it as one closed shape",
                    map.file, map.outline));
  if (outlines.size() != 1)
    throw InputError(fmt::format(
        "{}: layer \"{}\" holds {} closed shapes side by side ({}); say which is the outline: "
        "outline = {{ layer = \"{}\", around = [x, y] }} with a point inside it in the "
        "drawing's coordinates, or handle = \"...\", or pick = \"largest\"",
        map.file, map.outline, outlines.size(), outlines.empty() ? std::string("none") : list(),
        map.outline));
  return outlines.front();
}

std::string summary_of(const Site& site, const Rect& bounds, const LayerMap& map,
                       const std::string& unit_name) {
  const size_t arcs = arc_count(site.outline);
  std::string text = fmt::format("outline {} x {} mm", grouped(bounds.w), grouped(bounds.h));
  if (arcs) text += fmt::format(" with {} arc{}", arcs, arcs == 1 ? "" : "s");
  if (!map.openings.empty())
    text +=
        fmt::format("; {} opening{}", site.openings.size(), site.openings.size() == 1 ? "" : "s");
  if (!map.zones.empty()) {
    // By layer: "TREE_PIT exclude" for one, "20 TREE_PIT exclude" for twenty.
    text += fmt::format("; {} zone{} (", site.zones.size(), site.zones.size() == 1 ? "" : "s");
    for (size_t i = 0; i < map.zones.size(); ++i) {
      const ZoneLayer& z = map.zones[i];
      const auto n = std::count_if(site.zones.begin(), site.zones.end(), [&](const SiteZone& s) {
        return s.name == z.layer || s.name.rfind(z.layer + " ", 0) == 0;
      });
      text += fmt::format(
          "{}{}{} {}", i ? ", " : "", n > 1 ? fmt::format("{} ", n) : "", z.layer,
          z.rule == ZoneRule::exclude ? std::string("exclude") : fmt::format("value {}", z.value));
    }
    text += ")";
  }
  return text + fmt::format(" from {}, units {}", map.file, unit_name);
}

}  // namespace

std::vector<Contour> closed_regions(const Drawing& drawing, const std::string& layer,
                                    double unit_mm) {
  std::vector<Contour> regions;
  if (!(unit_mm > 0)) return regions;
  PassedOver passed;
  try {
    for (Closed& c :
         closed_on(drawing, layer, kJoinTolerance / unit_mm, "", "outline", unit_mm, passed))
      regions.push_back(std::move(c.path));
  } catch (const InputError&) {
    regions.clear();  // a layer left open or faulty forms no region to pick
  }
  return regions;
}

Site site_from(const Drawing& drawing, const LayerMap& map) {
  Site site;
  const std::vector<std::string> layers = layers_of(drawing);
  check_named(drawing, layers, map.outline, map.file, "the outline");
  for (const std::string& l : map.openings) check_named(drawing, layers, l, map.file, "openings");
  for (const ZoneLayer& z : map.zones) check_named(drawing, layers, z.layer, map.file, "a zone");
  std::string unit_name;
  const double mm = units_of(drawing, map, unit_name, site.notes);
  const double join_tolerance = kJoinTolerance / mm;

  PassedOver passed;
  const std::vector<Closed> outlines =
      closed_on(drawing, map.outline, join_tolerance, map.file, "outline", mm, passed);
  note_passed_over(passed, map.outline, site.notes);
  const Closed outline = picked_outline(outlines, map, drawing, join_tolerance);
  const Rect bounds = contour_bounds(outline.path);
  const std::array<double, 2> datum = datum_of(map, bounds, mm, join_tolerance);
  site.datum = {snapped(datum[0] * mm), snapped(datum[1] * mm)};
  site.unit_mm = mm;
  site.unit_name = unit_name;
  if (!outline.shapes.empty()) site.height_mm = outline.shapes.front()->height * mm;
  site.precision = drawing.precision;
  site.outline = counter_clockwise(to_mm(outline.path, datum, mm));
  const Rect extent = contour_bounds(site.outline);
  check_plausible(extent, map, unit_name, mm);
  const Polygon flat = flatten(site.outline, map.chord_tolerance);
  if (const auto crossing = first_crossing(flat))
    throw InputError(fmt::format(
        "{}: the outline {} on layer \"{}\" crosses itself at ({:g}, {:g}) in the drawing; an "
        "outline goes round the surface once",
        map.file, outline.handles, map.outline, (*crossing)[0] / mm + datum[0],
        (*crossing)[1] / mm + datum[1]));
  if (flat.size() < 3 || !(polygon_area(flat) >= kLeastArea))
    throw InputError(
        fmt::format("{}: the outline {} on layer \"{}\" encloses no area (under {:g} "
                    "mm²)",
                    map.file, outline.handles, map.outline, kLeastArea));
  if (extent.x < -1e-6 || extent.y < -1e-6)
    throw InputError(
        fmt::format("{}: the outline reaches ({:g}, {:g}) mm left of or below the "
                    "datum; set [layout.site] origin = \"outline\" or a point at or "
                    "below its bottom-left corner",
                    map.file, extent.x, extent.y));
  read_holes(drawing, map, flat, datum, mm, join_tolerance, site);

  site.summary = summary_of(site, extent, map, unit_name);
  if (site.datum[0] != 0 || site.datum[1] != 0)
    site.notes.push_back(
        fmt::format("the layout's datum (0, 0) is the drawing's point ({}, {}) "
                    "mm",
                    grouped(site.datum[0]), grouped(site.datum[1])));
  std::vector<std::string> ignored;
  for (const std::string& l : layers) {
    const bool named =
        l == map.outline ||
        std::find(map.openings.begin(), map.openings.end(), l) != map.openings.end() ||
        std::any_of(map.zones.begin(), map.zones.end(),
                    [&](const ZoneLayer& z) { return z.layer == l; });
    if (!named) ignored.push_back(l);
  }
  if (!ignored.empty()) {
    std::string names;
    for (const auto& l : ignored) names += (names.empty() ? "" : ", ") + l;
    site.notes.push_back("layers not named in [layout.site], ignored: " + names);
  }
  for (const std::string& l : drawing.hidden)
    if (l == map.outline ||
        std::find(map.openings.begin(), map.openings.end(), l) != map.openings.end())
      site.notes.push_back("layer \"" + l +
                           "\" is frozen or off in the drawing; read all the same");
  site.notes.insert(site.notes.end(), drawing.notes.begin(), drawing.notes.end());
  return site;
}

}  // namespace curdle::site
