// [layout.site]: file, outline, openings, zones, units and origin (patterns/README.md, "From
// your drawing"). The drawing is read through the recipe's RecipeFiles and turned into the
// surface by src/site; what it gives takes the place of layout.outline and [[layout.zones]].
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "layout/contour.h"
#include "layout/zone.h"
#include "recipe/layout_reader.h"
#include "site/site.h"

namespace curdle::reading {
namespace {

std::vector<std::string> read_layers(TableReader& r, const std::string& key) {
  const toml::node* n = r.get(key);
  std::vector<std::string> layers;
  if (!n) return layers;
  const std::string allowed =
      "must be a layer's name or a list of them, e.g. [\"A-GLAZ\", \"A-DOOR\"]";
  if (const auto one = n->value<std::string>()) {
    layers.push_back(*one);
  } else if (const toml::array* a = n->as_array(); a && a->size() <= 100) {
    for (const toml::node& item : *a) {
      const auto name = item.value<std::string>();
      if (!name) r.fail(key, allowed);
      layers.push_back(*name);
    }
  } else {
    r.fail(key, allowed);
  }
  for (const std::string& l : layers)
    if (l.empty() || l.size() > 255) r.fail(key, allowed + "; a name of 1 to 255 characters");
  return layers;
}

// `key` as a point of the drawing, [x, y] in its own coordinates (finite, within 10^12 of its
// origin); nullopt where the key is absent, and `allowed` said where it is no such point.
std::optional<std::array<double, 2>> read_drawing_point(TableReader& r, const std::string& key,
                                                        const std::string& allowed) {
  const toml::node* n = r.get(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  const auto x = a && a->size() == 2 ? finite_number(a->get(0)) : std::nullopt;
  const auto y = a && a->size() == 2 ? finite_number(a->get(1)) : std::nullopt;
  if (!x || !y || std::fabs(*x) > 1e12 || std::fabs(*y) > 1e12) r.fail(key, allowed);
  return std::array<double, 2>{*x, *y};
}

site::ZoneLayer read_zone_layer(TableReader& r, size_t values) {
  site::ZoneLayer z;
  z.layer = read_name(r, "layer", "a layer's name").value_or("");
  if (z.layer.empty() || z.layer.size() > 255)
    r.fail("layer", "must be the name of the drawing's layer that holds the zone's outlines");
  const std::string rule = read_string(r, "rule", "\"exclude\" or \"value\"").value_or("exclude");
  if (rule == "exclude") {
    if (r.get("value"))
      r.fail("value", "is for rule = \"value\"; an excluded zone has no elements");
  } else if (rule == "value") {
    z.rule = ZoneRule::value;
    z.value = static_cast<uint32_t>(
        read_int(r, "value", 0, 0, static_cast<int64_t>(values) - 1, /*required=*/true));
  } else {
    r.fail("rule", "must be \"exclude\" (no elements) or \"value\" with value = N");
  }
  z.around = read_drawing_point(r, "around",
                                "must be [x, y]: a point inside the one shape of the layer that "
                                "is the zone, in the drawing's own coordinates and units");
  return z;
}

void read_units_and_origin(TableReader& r, site::LayerMap& map) {
  if (const auto units = read_string(r, "units", "a unit")) {
    map.unit_mm = site::unit_mm(*units);
    map.unit_name = *units;
    if (map.unit_mm == 0)
      r.fail("units",
             "must be \"mm\", \"cm\", \"dm\", \"m\", \"in\" or \"ft\": what one unit "
             "of the drawing is");
  }
  const toml::node* n = r.get("origin");
  if (!n) return;
  const std::string allowed =
      "must be \"drawing\" (its origin is the layout's datum), \"outline\" (the outline's "
      "bottom-left corner is) or [x, y] in the drawing's units";
  if (const auto word = n->value<std::string>()) {
    if (*word == "outline")
      map.origin_at_outline = true;
    else if (*word == "drawing")
      map.origin = std::array<double, 2>{0, 0};
    else
      r.fail("origin", allowed);
    return;
  }
  map.origin = read_drawing_point(r, "origin", allowed);
}

// `file`: a drawing's name, a .dxf or .svg relative to the recipe; where `or_model`, also a
// massing model's (.glb, .gltf), whose nodes' footprints are its layers.
std::string read_drawing_name(TableReader& r, const std::string& what, bool or_model = false) {
  const std::string file = read_string(r, "file", "a file name").value_or("");
  std::string lower = file;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  auto ends = [&](const std::string& e) {
    return lower.size() > e.size() && lower.compare(lower.size() - e.size(), e.size(), e) == 0;
  };
  const bool model = or_model && (ends(".glb") || ends(".gltf"));
  if (file.empty() || file.size() > 1024 || (!ends(".dxf") && !ends(".svg") && !model))
    r.fail("file", "must name the " + what + ", a .dxf or .svg file" +
                       (or_model ? " (or a massing model, .glb or .gltf)" : "") +
                       " relative to the recipe (in CAD: save as DXF; in Inkscape or "
                       "Illustrator: save as SVG)");
  return file;
}

// `key` (outline, plan): the layer that holds the surface's outline, or a table that also
// picks one of its shapes: { layer = "A-SITE", around = [x, y] } (the smallest shape around a
// point in the drawing's coordinates), handle = "2F" (an entity's), or pick = "largest".
void read_outline_layer(TableReader& r, const std::string& key, const std::string& example,
                        site::LayerMap& map) {
  const toml::node* n = r.get(key);
  const toml::table* t = n ? n->as_table() : nullptr;
  if (!t) {
    const auto layers = read_layers(r, key);
    if (layers.size() != 1)
      r.fail(key, "must name the one layer that holds the outline, e.g. \"" + example +
                      "\", or be a table { layer = \"" + example +
                      "\", around = [x, y] } that picks one of its shapes");
    map.outline = layers.front();
    return;
  }
  TableReader pr(*t, r.key_path(key), r.source(), {"layer", "around", "handle", "pick"});
  map.outline = read_name(pr, "layer", "a layer's name").value_or("");
  if (map.outline.empty() || map.outline.size() > 255)
    pr.fail("layer",
            "must name the drawing's layer that holds the outline, e.g. \"" + example + "\"");
  int ways = 0;
  map.pick.around = read_drawing_point(pr, "around",
                                       "must be [x, y]: a point inside the outline, in the "
                                       "drawing's own coordinates and units (as CAD shows them)");
  ways += map.pick.around.has_value();
  if (pr.get("handle")) {
    map.pick.handle = read_string(pr, "handle", "an entity's handle").value_or("");
    if (map.pick.handle.empty() || map.pick.handle.size() > 16)
      pr.fail("handle",
              "must be the handle of the outline's entity, as CAD lists it (e.g. \"2F\")");
    ++ways;
  }
  if (pr.get("pick")) {
    if (read_string(pr, "pick", "\"largest\"").value_or("") != "largest")
      pr.fail("pick", "must be \"largest\": the largest of the layer's closed shapes");
    map.pick.largest = true;
    ++ways;
  }
  if (ways > 1) pr.fail("around", "picks the outline one way: around, handle or pick, not several");
  pr.report_unused("is not a key of the outline's table (layer, around, handle, pick)");
}

// The drawing that `r`'s table (`table`) names in `file`, read beside the recipe and turned into
// a site by `map`; one that cannot be read or laid is refused at that `file`.
site::Site drawn_site(const TableReader& r, const toml::node& table, const site::LayerMap& map,
                      const LayoutSpec& spec) {
  if (!r.source().files)
    r.fail("file",
           "names a drawing, which is read only where the recipe is a file: run curdle on the "
           "recipe's file");
  const SourceLocation where = locate(r.source(), table.source(), r.key_path("file"));
  const std::string bytes = r.source().files->read(map.file, where, site::kMostDrawingBytes);
  try {
    return site::site_from(site::read_drawing(bytes, map.file, spec.chord_tolerance, map.unit_mm),
                           map);
  } catch (const InputError& e) {  // the drawing's own fault, located at the recipe's key
    r.fail("file", e.message());
  }
}

site::LayerMap read_layer_map(TableReader& r, const LayoutSpec& spec, size_t values) {
  site::LayerMap map;
  map.file = read_drawing_name(r, "site's drawing");
  read_outline_layer(r, "outline", "A-OTLN", map);
  map.openings = read_layers(r, "openings");
  if (const toml::node* n = r.get("zones")) {
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables() || a->size() > 100)
      r.fail("zones",
             "must be [[layout.site.zones]] tables (at most 100), each with layer and "
             "rule (\"exclude\", or \"value\" with value = N)");
    for (size_t i = 0; i < a->size(); ++i) {
      TableReader zr(*a->get(i)->as_table(), r.key_path("zones." + std::to_string(i)), r.source(),
                     {"layer", "rule", "value", "around"});
      map.zones.push_back(read_zone_layer(zr, values));
    }
  }
  read_units_and_origin(r, map);
  map.chord_tolerance = spec.chord_tolerance;
  return map;
}

Zone zone_of(const std::string& name, ZoneRule rule, uint32_t value, const Contour& contour,
             double tolerance) {
  Zone z;
  z.name = name;
  z.rule = rule;
  z.value = value;
  z.polygon = flatten(contour, tolerance);
  if (has_arcs(contour)) z.contour = contour;
  if (rule == ZoneRule::exclude)
    if (const auto rects = as_rectangles(z.polygon)) z.rects = *rects;
  return z;
}

// Where the layout lies in its drawing, for outputs laid back onto it: DXF drawings only (an
// SVG's own frame runs y down from its page's corner).
std::optional<SiteFrame> frame_of(const site::Site& s, const std::string& file) {
  std::string lower = file;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower.size() < 4 || lower.compare(lower.size() - 4, 4, ".dxf") != 0) return std::nullopt;
  static const std::map<std::string, int> kInsunits = {{"in", 1}, {"ft", 2}, {"mm", 4},
                                                       {"cm", 5}, {"m", 6},  {"dm", 14}};
  const auto code = kInsunits.find(s.unit_name);
  if (code == kInsunits.end()) return std::nullopt;
  SiteFrame f;
  f.file = file;
  f.unit_mm = s.unit_mm;
  f.unit_name = s.unit_name;
  f.insunits = code->second;
  f.datum = {s.datum[0] / s.unit_mm, s.datum[1] / s.unit_mm};
  f.precision = s.precision;
  return f;
}

}  // namespace

void read_site(TableReader& r, const Design& design, LayoutSpec& spec) {
  const toml::node* n = r.get("site");
  if (!n) return;
  if (r.get("outline"))
    r.fail("outline", "is given by [layout.site]'s drawing; give one or the other");
  const toml::table* t = n->as_table();
  if (!t) r.fail("site", "must be a table: [layout.site] with file, outline and more");
  TableReader sr(*t, r.key_path("site"), r.source(),
                 {"file", "outline", "openings", "zones", "units", "origin"});
  const size_t values = size_t{1} << design.curds.size();
  site::LayerMap map = read_layer_map(sr, spec, values);
  if (!map.zones.empty() && !spec.kind->takes_zones())
    sr.fail("zones", "are for tile, paving, facade and park layouts");
  sr.report_unused("is not a [layout.site] key");
  const site::Site s = drawn_site(sr, *t, map, spec);
  spec.outline = flatten(s.outline, spec.chord_tolerance);
  if (has_arcs(s.outline)) spec.outline_contour = s.outline;
  const Rect bounds = contour_bounds(s.outline);
  if (spec.size) {
    if (bounds.right() > (*spec.size)[0] + 1e-6 || bounds.top() > (*spec.size)[1] + 1e-6)
      sr.fail("file", fmt::format("{}: the outline reaches {:g} x {:g} mm, beyond the surface's "
                                  "size of {:g} x {:g} mm; leave the size out, and the outline "
                                  "gives it",
                                  map.file, bounds.right(), bounds.top(), (*spec.size)[0],
                                  (*spec.size)[1]));
  } else {
    spec.size = std::array<double, 2>{bounds.right(), bounds.top()};
  }
  size_t number = 0;
  for (const Contour& o : s.openings) {
    ++number;
    const auto rect = as_rectangle(o);
    if (rect && spec.kind->take_opening(spec, {rect->x, rect->y, rect->w, rect->h})) continue;
    if (!spec.kind->takes_zones())
      sr.fail("openings", "are for tile, paving, facade and park layouts");
    spec.zones.push_back(
        zone_of(fmt::format("opening {}", number), ZoneRule::exclude, 0, o, spec.chord_tolerance));
  }
  for (const site::SiteZone& z : s.zones) {
    spec.zones.push_back(zone_of(z.name, z.rule, z.value, z.contour, spec.chord_tolerance));
  }
  spec.site_summary = s.summary;
  spec.site_notes = s.notes;
  spec.site_frame = frame_of(s, map.file);
}

Contour read_site_plan(TableReader& building, const LayoutSpec& spec, std::string& summary,
                       double& model_height) {
  const toml::table* t = read_table(building, "site");
  if (!t)
    building.fail("site", "must be a table: [layout.building.site] with file and plan (a layer)");
  TableReader sr(*t, building.key_path("site"), building.source(),
                 {"file", "plan", "units", "origin"});
  site::LayerMap map;
  map.file = read_drawing_name(sr, "plan's drawing", true);
  read_outline_layer(sr, "plan", "A-WALL", map);
  read_units_and_origin(sr, map);
  map.chord_tolerance = spec.chord_tolerance;
  sr.report_unused("is not a [layout.building.site] key (file, plan, units, origin)");
  const site::Site s = drawn_site(sr, *t, map, spec);
  summary = "plan: " + s.summary;
  model_height = s.height_mm;
  return s.outline;
}

std::vector<BuildingOpening> read_site_elevations(TableReader& building, const LayoutSpec& spec) {
  std::vector<BuildingOpening> out;
  const toml::array* a = building.get("elevations")->as_array();
  if (!a || !a->is_array_of_tables() || a->size() > 1000)
    building.fail("elevations",
                  "must be [[layout.building.elevations]] tables, each with facade, file, wall "
                  "(the façade's outline layer) and openings (layers)");
  for (size_t i = 0; i < a->size(); ++i) {
    TableReader er(*a->get(i)->as_table(), building.key_path("elevations." + std::to_string(i)),
                   building.source(), {"facade", "file", "wall", "openings", "units"});
    const std::string facade = read_name(er, "facade", "a façade's name").value_or("");
    if (facade.empty()) er.fail("facade", "must name the façade the drawing is of: \"S\", \"E2\"");
    site::LayerMap map;
    map.file = read_drawing_name(er, "façade's elevation");
    const auto wall = read_layers(er, "wall");
    if (wall.size() != 1)
      er.fail("wall", "must name the one layer that holds the façade's outline, e.g. \"A-WALL\"");
    map.outline = wall.front();
    map.openings = read_layers(er, "openings");
    if (map.openings.empty()) er.fail("openings", "must name the layers of the windows and doors");
    read_units_and_origin(er, map);
    map.origin_at_outline = true;  // the façade's own x and y: from its bottom-left corner
    map.chord_tolerance = spec.chord_tolerance;
    er.report_unused("is not a [[layout.building.elevations]] key");
    const site::Site s = drawn_site(er, *a->get(i), map, spec);
    for (const Contour& o : s.openings) {
      const auto r = as_rectangle(o);
      if (!r)
        er.fail("openings", map.file + ": a building's openings are rectangles in its elevation");
      // A door stands on the base; a window above it.
      out.push_back({facade, *r, r->y < 1 ? "door" : "window"});
    }
  }
  return out;
}

}  // namespace curdle::reading
