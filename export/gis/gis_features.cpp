#include "export/gis/gis_features.h"

#include <cmath>
#include <map>

#include "layout/element_zone.h"
#include "layout/piece.h"
#include "layout/piece_rows.h"
#include "layout/zone.h"

namespace curdle {
namespace {

using T = GisField::Type;

// The schedule's columns, in its units, as fields (curd bits are the value's).
const std::vector<GisField> kFields{{"element_id", T::text},
                                    {"lot", T::text},
                                    {"level", T::integer},
                                    {"row", T::integer},
                                    {"column", T::integer},
                                    {"x_mm", T::real},
                                    {"y_mm", T::real},
                                    {"z_mm", T::real},
                                    {"width_mm", T::real},
                                    {"height_mm", T::real},
                                    {"depth_mm", T::real},
                                    {"area_m2", T::real},
                                    {"stock_width_mm", T::real},
                                    {"stock_height_mm", T::real},
                                    {"value", T::integer},
                                    {"element_type", T::text},
                                    {"colour", T::text},
                                    {"material", T::text},
                                    {"cut", T::integer},
                                    {"opening_diameter_mm", T::real},
                                    // planting.csv's and furniture.csv's (null on other pieces)
                                    {"species", T::text},
                                    {"girth_cm", T::text},
                                    {"root_ball_mm", T::real},
                                    {"pit_width_mm", T::real},
                                    {"pit_length_mm", T::real},
                                    {"facing_deg", T::integer},
                                    {"zone", T::text}};

// Text as a value: empty text is null, as GIS readers expect of a column a piece has not.
GisValue text(std::string v) {
  if (v.empty()) return {};
  return v;
}
GisValue number(const std::optional<double>& v) {
  if (!v) return {};
  return *v;
}
GisValue given(double v) {
  if (v > 0) return v;
  return {};
}
GisValue whole(std::int64_t v) { return v; }

// A table name from an element type: "paving tile" -> "paving_tile".
std::string table_name(const std::string& type) {
  std::string out;
  for (const char c : type) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    if (c >= 'A' && c <= 'Z')
      out += static_cast<char>(c - 'A' + 'a');
    else
      out += keep ? c : '_';
  }
  return out.empty() || (out[0] >= '0' && out[0] <= '9') ? "elements_" + out : out;
}

// A tree's or a bench's planting columns as planting.csv and furniture.csv give them, and every
// piece's zone as the schedules book it.
void add_planting_values(const Layout& layout, const Element& e, std::vector<GisValue>& out) {
  const size_t first = out.size();
  out.resize(first + 7);
  if (e.stands) {
    const PlantingSpec& p = planting_of(layout, e);
    out[first] = text(p.species);
    out[first + 1] = text(p.girth_text());
    out[first + 2] = given(p.root_ball);
    out[first + 3] = given(p.pit[0]);
    out[first + 4] = given(p.pit[1]);
    if (!e.circle) out[first + 5] = whole(static_cast<int>(e.turn));  // a bench's facing
  }
  out[first + 6] = text(zone_of_element(layout, e));
}

std::vector<GisValue> values_of(const ScheduleRow& r) {
  return {text(r.id),
          text(r.lot),
          r.level ? whole(*r.level) : GisValue{},
          whole(r.row),
          whole(r.column),
          r.x,
          r.y,
          r.z,
          r.width,
          r.height,
          number(r.depth),
          area_m2(r.area),
          number(r.stock_width),
          number(r.stock_height),
          whole(r.value),
          text(r.element_type),
          text(r.colour),
          text(r.material),
          whole(r.cut ? 1 : 0),
          number(r.opening_diameter)};
}

}  // namespace

std::array<double, 2> map_point(const Layout& layout, double x_mm, double y_mm) {
  const double x = x_mm / 1000, y = y_mm / 1000;
  if (!layout.georef) return {x, y};
  const Georef& g = *layout.georef;
  const double a = g.rotation * 3.14159265358979323846 / 180;
  return {g.easting + x * std::cos(a) - y * std::sin(a),
          g.northing + x * std::sin(a) + y * std::cos(a)};
}

GisDataset gis_features(const Layout& layout) {
  GisDataset data;
  data.epsg = layout.georef ? layout.georef->epsg : 0;
  data.fields = kFields;
  std::map<std::string, size_t> layer_of;  // table name -> index, in order of first piece
  for (size_t i = 0; i < layout.elements.size(); ++i) {
    const ScheduleRow row = schedule_row(layout, i);
    const std::string name = table_name(row.element_type);
    auto [at, added] = layer_of.try_emplace(name, data.layers.size());
    if (added) data.layers.push_back({name, {}});
    GisFeature f;
    f.values = values_of(row);
    add_planting_values(layout, layout.elements[i], f.values);
    for (const Outline& part : row.outlines) {
      std::vector<Ring> rings;
      for (const Ring& ring : part.rings) {
        Ring mapped;
        for (const auto& [x, y] : ring) mapped.push_back(map_point(layout, x, y));
        rings.push_back(std::move(mapped));
      }
      f.polygons.push_back(std::move(rings));
    }
    data.layers[at->second].features.push_back(std::move(f));
  }
  return data;
}

}  // namespace curdle
