#include "app/site_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <iterator>

#include "curdle/error.h"
#include "layout/zone.h"
#include "site/reading_memory.h"
#include "site/site.h"

namespace curdle::app {
namespace {

using nlohmann::ordered_json;

std::string number(double v) { return fmt::format("{:.9g}", v); }

// A contour as the recipe writes it: [[x, y], [x, y, bulge], ...].
std::string contour_toml(const Contour& c) {
  std::string text = "[";
  for (size_t i = 0; i < c.size(); ++i) {
    // fmt rather than chains of string +, on which GCC 12 warns falsely (-Wrestrict).
    fmt::format_to(std::back_inserter(text), "{}[{},{}", i ? "," : "", number(c[i].x),
                   number(c[i].y));
    if (c[i].bulge != 0) fmt::format_to(std::back_inserter(text), ",{:.17g}", c[i].bulge);
    text += ']';
  }
  return text + "]";
}

ordered_json contour_json(const Contour& c) {
  ordered_json points = ordered_json::array();
  for (const ContourVertex& v : c)
    points.push_back(v.bulge != 0 ? ordered_json{v.x, v.y, v.bulge} : ordered_json{v.x, v.y});
  return points;
}

site::Drawing read_drawing(const SiteStudyRequest& r, double tolerance, double unit_mm,
                           const GenerateOptions& limits) {
  std::string ending = r.name.size() >= 4 ? r.name.substr(r.name.size() - 4) : r.name;
  for (char& c : ending) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ending != ".svg" && ending != ".dxf")
    throw InputError(parameter("name"), "'" + r.name + "' is not a .dxf or .svg drawing");
  try {
    site::check_reading_memory(r.bytes, r.name, limits.max_memory_bytes, limits.memory_limit_hint);
    return site::read_drawing(r.bytes, r.name, tolerance, unit_mm);
  } catch (const InputError& e) {
    throw InputError(parameter("name"), e.message());
  }
}

ordered_json layers_json(const site::Drawing& drawing) {
  ordered_json layers = ordered_json::array();
  for (const std::string& name : site::layers_of(drawing)) {
    size_t shapes = 0, closed = 0;
    for (const site::Shape& s : drawing.shapes)
      if (s.layer == name) ++shapes, closed += s.closed;
    layers.push_back({{"name", name}, {"shapes", shapes}, {"closed", closed}});
  }
  return layers;
}

// Each layer's closed regions, thinned to at most 512 points a ring for the page's picture, so
// that a click can pick the outline where a layer holds several.
ordered_json regions_json(const site::Drawing& drawing, double unit_mm, double tolerance_mm) {
  ordered_json regions = ordered_json::array();
  size_t points = 0;
  for (const std::string& layer : site::layers_of(drawing)) {
    ordered_json rings = ordered_json::array();
    for (const Contour& c : site::closed_regions(drawing, layer, unit_mm)) {
      const Polygon flat = flatten(c, tolerance_mm / unit_mm);
      const size_t step = std::max<size_t>(1, (flat.size() + 511) / 512);
      ordered_json ring = ordered_json::array();
      for (size_t i = 0; i < flat.size(); i += step) ring.push_back({flat[i][0], flat[i][1]});
      points += ring.size();
      if (points > kMostRegionPoints) return regions;  // enough to pick from; the rest unshown
      rings.push_back(std::move(ring));
    }
    if (!rings.empty()) regions.push_back({{"layer", layer}, {"rings", std::move(rings)}});
  }
  return regions;
}

// "x,y": two finite numbers in the C locale, as the drawing's coordinates.
std::array<double, 2> point_of(const std::string& text) {
  std::array<double, 2> p{};
  const char* at = text.data();
  const char* end = text.data() + text.size();
  for (size_t i = 0; i < 2; ++i) {
    const auto [next, error] = std::from_chars(at, end, p[i]);
    const bool separated = i == 0 ? next != end && *next == ',' : next == end;
    if (error != std::errc() || !std::isfinite(p[i]) || !separated)
      throw InputError(parameter("around"),
                       "'" + text.substr(0, 80) +
                           "' is not a point: give x,y in the drawing's coordinates, two finite "
                           "numbers");
    at = next + 1;
  }
  return p;
}

}  // namespace

ordered_json study_site(const Run& run, const SiteStudyRequest& r) {
  if (!run.recipe.layout || !run.recipe.layout->kind->takes_zones())
    throw InputError(parameter("name"),
                     "a site drawing is laid by a tile, paving or facade layout; this recipe's "
                     "layout is not one");
  const LayoutSpec& spec = *run.recipe.layout;
  const double unit_mm = r.units.empty() ? 0 : site::unit_mm(r.units);
  if (!r.units.empty() && unit_mm == 0)
    throw InputError(parameter("units"), "must be mm, cm, dm, m, in or ft");
  const site::Drawing drawing = read_drawing(r, spec.chord_tolerance, unit_mm, run.generate);
  ordered_json j{{"file", r.name},
                 {"format", drawing.format},
                 {"units", drawing.unit_name},
                 {"layers", layers_json(drawing)},
                 {"hidden", drawing.hidden},
                 {"notes", drawing.notes}};
  if (r.outline.empty()) {
    const double region_unit = unit_mm > 0 ? unit_mm : drawing.unit_mm > 0 ? drawing.unit_mm : 1;
    j["regions"] = regions_json(drawing, region_unit, spec.chord_tolerance);
    return j;
  }
  site::LayerMap map;
  map.file = r.name;
  map.outline = r.outline;
  if (!r.around.empty()) map.pick.around = point_of(r.around);
  map.openings = r.openings;
  for (const std::string& z : r.zones) map.zones.push_back({z, ZoneRule::exclude, 0});
  map.unit_mm = unit_mm;
  map.unit_name = r.units;
  map.chord_tolerance = spec.chord_tolerance;
  site::Site s;
  try {
    s = site::site_from(drawing, map);
  } catch (const InputError& e) {
    throw InputError(parameter("outline"), e.message());
  }
  std::vector<std::string> sets{"layout.outline=" + contour_toml(s.outline)};
  ordered_json zones = ordered_json::array();
  std::string windows;
  LayoutSpec probe = spec;  // asks the kind whether it takes a rectangle as its own opening
  size_t number_of = 0;
  for (const Contour& o : s.openings) {
    ++number_of;
    if (const auto rect = as_rectangle(o)) {
      const Rect& b = *rect;
      if (probe.kind->take_opening(probe, {b.x, b.y, b.w, b.h})) {
        fmt::format_to(std::back_inserter(windows), "{}[{},{},{},{}]", windows.empty() ? "" : ",",
                       number(b.x), number(b.y), number(b.w), number(b.h));
        continue;
      }
    }
    zones.push_back({{"name", fmt::format("opening {}", number_of)},
                     {"rule", "exclude"},
                     {"polygon", contour_json(o)}});
  }
  if (!windows.empty()) sets.push_back("layout.openings=[" + windows + "]");
  for (const site::SiteZone& z : s.zones)
    zones.push_back({{"name", z.name}, {"rule", "exclude"}, {"polygon", contour_json(z.contour)}});
  j["site"] = {{"summary", s.summary}, {"notes", s.notes}, {"sets", sets}, {"zones", zones}};
  return j;
}

}  // namespace curdle::app
