// A drawing as the site readers give it (dxf_reader.h, svg_reader.h): shapes on layers in the
// drawing's own units and coordinates, blocks already placed, before they are turned into a
// surface's outline, openings and zones (site.h). Nothing here knows the file's format.
// A drawing that cannot be read or used is an InputError without a location (what is wrong,
// naming the file, layer and entity, and what to do); the recipe reader adds the recipe's key.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "curdle/error.h"
#include "layout/contour.h"

namespace curdle::site {

// The layer of an SVG's shapes that lie in no layer (no group at the top, or outside Inkscape's
// layers), so that a recipe can name it.
inline constexpr const char* kRootLayer = "(root)";

struct Shape {
  std::string layer;
  // Other names a recipe may pick the shape by: an SVG's named groups inside its layer, and the
  // shape's own id or label.
  std::vector<std::string> also;
  std::string handle;  // the entity's handle (DXF) or id (SVG), for messages; may be empty
  std::string entity;  // "LWPOLYLINE", "LINE", "ARC", "CIRCLE", "path", ...
  Contour path;        // in drawing units; an open shape's last vertex's bulge is unused
  bool closed = false;
  int insert = -1;            // the top-level block reference it was placed by; -1: none
  bool flattened = false;     // an ellipse or spline, approximated by chords
  std::string block;          // the block it is drawn in, for messages; empty: model space
  std::string insert_handle;  // the handle of the top-level INSERT that placed it
  // An open polyline drawn with width: the area it covers (wide_polyline.h), taken where the
  // shape is not joined into an outline with others; empty: no width.
  Contour strip;
  double height = 0;  // a massing model's node: how high it stands, drawing units
  // Why the shape could not be read (a spline whose knots do not fit): refused where a layer
  // the recipe names holds it, passed over elsewhere.
  std::string fault;
};

struct Drawing {
  std::string format;  // "DXF", "SVG"
  // Millimetres per drawing unit, as the drawing says; 0 when it does not ($INSUNITS 0).
  double unit_mm = 0;
  std::string unit_name;  // as the drawing says it: "mm", "m", "in", ...
  std::vector<Shape> shapes;
  std::vector<std::string> hidden;  // layers frozen or off in the drawing (read all the same)
  std::vector<std::string> notes;   // what a reader approximated or passed over
  int precision = 4;                // decimals of the drawing's coordinates ($LUPREC), for messages
};

// Whether `s` lies on `layer`, or is picked by one of its other names.
inline bool on_layer(const Shape& s, const std::string& layer) {
  return s.layer == layer || std::find(s.also.begin(), s.also.end(), layer) != s.also.end();
}

// Every layer that holds a shape, in the order first seen.
inline std::vector<std::string> layers_of(const Drawing& drawing) {
  std::vector<std::string> layers;
  for (const Shape& s : drawing.shapes)
    if (std::find(layers.begin(), layers.end(), s.layer) == layers.end()) layers.push_back(s.layer);
  return layers;
}

// What a reader may hold at most, so that a hostile file is refused with a clear limit.
inline constexpr size_t kMostDrawingBytes = size_t{64} << 20;
inline constexpr size_t kMostShapes = 200000;
inline constexpr size_t kMostVertices = 2000000;
// How far from the plan's plane a vertex may stand before a shape is off it, drawing units.
inline constexpr double kPlaneTolerance = 1e-6;

}  // namespace curdle::site
