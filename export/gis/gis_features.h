// The layout as GIS features, for layout.gpkg: one feature per piece (a row of schedule.csv)
// with the schedule's attributes and its shape as laid, in metres; one layer per kind of
// element ("paving tile", "tree", "bench", "opening"), as a GIS user styles and filters them.
// With layout.georef the coordinates are the project's CRS (EPSG code, the datum's easting and
// northing, the layout's rotation); without it, metres from the layout's bottom-left corner.
// No GDAL here: gpkg.h hands the features to the module that writes them.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "layout/layout.h"

namespace curdle {

struct GisField {
  enum class Type { integer, real, text };
  std::string name;
  Type type = Type::text;
};

// One attribute, of its field's type; none is null. Numbers go to GDAL as numbers: written as
// text, GDAL spent as long parsing them back as the rest of its work on a feature.
using GisValue = std::variant<std::monostate, std::int64_t, double, std::string>;

struct GisFeature {
  std::vector<std::vector<Ring>> polygons;  // each an outer ring then its holes, in metres
  std::vector<GisValue> values;             // one per field
};

struct GisLayer {
  std::string name;  // a table name: lower-case ASCII letters, digits and '_'
  std::vector<GisFeature> features;
};

struct GisDataset {
  int epsg = 0;                  // 0: no CRS (local metres)
  std::vector<GisField> fields;  // the same for every layer
  std::vector<GisLayer> layers;
};

// Where the layout's point (x, y) in mm lies in the dataset's coordinates, metres.
std::array<double, 2> map_point(const Layout& layout, double x_mm, double y_mm);

GisDataset gis_features(const Layout& layout);

}  // namespace curdle
