// The recipe's [layout]: each kind has its own reader, which owns its keys (any other key is
// reported, with a did-you-mean) and checks them against the design.
#pragma once

#include <optional>

#include "building/building.h"
#include "layout/layout.h"
#include "recipe/toml_reader.h"

namespace curdle::reading {

// The [layout] table, or std::nullopt when there is none: its kind (kinds/registry.h) reads
// its own keys, and a key present that no reader read is refused. A fixed floor, wall, sheet or
// line sizes the field when `field_given` is false, and must fit in it when true.
std::optional<LayoutSpec> read_layout(TableReader& top, Design& design, bool field_given);

// Every key a [layout] of this kind takes: those every kind takes, then the kind's own.
std::vector<std::string> layout_keys(const LayoutKind& kind);

// Keys every kind takes: the schedules' ordering and the drawing's colours and scale.
void read_ordering(TableReader& r, LayoutSpec& spec);
void read_value_colours(TableReader& r, const Design& design, LayoutSpec& spec);
void read_drawing_scale(TableReader& r, LayoutSpec& spec);

// What the surface kinds (tile, paving, facade, perforation, park) call their keys.
struct SurfaceKeys {
  const char* module_key;  // the element: "tile", "panel", "cell"
  const char* size_key;    // the surface: "size", "floor", "wall", "sheet", "area"
  bool size_required;
  bool joint;       // takes layout.joint
  bool grid_moves;  // origin = "centre" allowed: the grid is centred on the surface
};
// Their keys: element, joint, surface size, corner, colours and drawing.
std::vector<std::string> surface_keys(const SurfaceKeys& k);
void read_surface(TableReader& r, const SurfaceKeys& k, const Design& design, LayoutSpec& spec);
// layout.bond, zones, min_cut and shift (tile, paving, facade), after the surface.
void read_cut_rules(TableReader& r, const Design& design, LayoutSpec& spec);
// The field a fixed surface needs: sized by it, or checked to hold it.
void size_field(TableReader& r, const std::string& size_key, Design& design, const LayoutSpec& spec,
                bool field_given);
// layout.outline (tile, paving, facade, perforation, park): the surface as a polygon; its
// bounding rectangle is the size when the size key is left out.
void read_outline(TableReader& r, LayoutSpec& spec);
// [layout.site] (tile, paving, facade, perforation, park): the outline, openings and zones read
// from the architect's drawing (src/site), the outline's bounding rectangle the size when the
// size key is left out. Openings become the kind's own where it takes rectangles (a façade's
// windows), else excluded zones.
void read_site(TableReader& r, const Design& design, LayoutSpec& spec);
// The vertices under `key`, each [x, y] or [x, y, bulge] (bulge within ±1000): `least` to `most`
// of them, each coordinate within ±`reach` mm; else `allowed` is the message.
Contour read_vertices(TableReader& r, const std::string& key, const std::string& allowed,
                      size_t least, size_t most, double reach);

// A polygon's corners under `key`, each [x, y] or [x, y, bulge]: the contour with its arcs
// (empty where it has none), and its polygon with the arcs as chords within `tolerance`.
struct ReadContour {
  Contour contour;
  Polygon polygon;
};
ReadContour read_contour(TableReader& r, const std::string& key, double tolerance);

// [layout.building.site]: the building's plan (its outer face) from a layer of the architect's
// drawing, arcs kept, in mm from the drawing's datum (file, plan, units, origin as [layout.site]);
// `summary` says what was read.
// `model_height`: how high the plan's node stands where it is read from a massing model (mm),
// else 0.
Contour read_site_plan(TableReader& building, const LayoutSpec& spec, std::string& summary,
                       double& model_height);

// [[layout.building.elevations]]: each façade's windows and doors from its elevation drawing
// (facade, file, wall: the façade's outline layer, openings: layers, units), in the façade's
// own mm from the outline's bottom-left corner; an opening on the base is a door.
std::vector<BuildingOpening> read_site_elevations(TableReader& building, const LayoutSpec& spec);

// [layout.building] (facade): a building's plan or a free-standing wall's path, its height,
// base, unit depth and openings (building/building.h), and the envelope they make, checked
// where they were read. `bent_by_default`: units on an arc are bent to it unless arcs says
// otherwise (a screen's rolled sheets).
struct ReadBuilding {
  BuildingKeys keys;
  Envelope envelope;
};
ReadBuilding read_building(TableReader& layout, const LayoutSpec& spec,
                           bool bent_by_default = false);

// [[layout.zones]], after the surface's size (tile, paving, facade).
void read_zones(TableReader& r, const Design& design, LayoutSpec& spec);

}  // namespace curdle::reading
