// Layouts: the overlay's values turned into physical elements in millimetres — tiles,
// paving, façade panels — the way Cirovic (2014) maps curds onto architecture (figs. 1, 3, 7).
// Plain data: exporters draw it (SVG, PNG) and schedule it.
//
// Coordinates are millimetres from the layout's origin, x to the right and y up.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "curdle/check.h"
#include "curdle/curd.h"
#include "layout/block_views.h"
#include "layout/element_id.h"
#include "layout/envelope_frames.h"
#include "layout/fabrication_sheets.h"
#include "layout/geometry.h"
#include "layout/layout_kind.h"
#include "layout/planting_spec.h"
#include "layout/surface_frame.h"

namespace curdle {

// A zone of a surface ([[layout.zones]]): a rectangle or simple polygon in millimetres from the
// surface's bottom-left corner that either keeps elements out (planters, drains, columns:
// pieces are cut along it as at an opening) or gives its value to every element whose centre
// it holds (entrance bands, borders). Where zones overlap, the first listed decides.
enum class ZoneRule { exclude, value };
struct Zone {
  std::string name;
  ZoneRule rule = ZoneRule::exclude;
  uint32_t value = 0;       // rule value: what its elements take
  Polygon polygon;          // a rect is kept as its four corners; arcs as chords
  std::vector<Rect> rects;  // exclude: the polygon as rectangles (its edges run along x and y)
  Contour contour;          // with its arcs, where it has any (empty: the polygon's edges)
};

// What a zone holds once laid, for the report.
struct ZoneCount {
  std::string name;
  ZoneRule rule = ZoneRule::exclude;
  uint32_t value = 0;
  Polygon polygon;  // as the zone was given
  double area = 0;  // of the zone on the surface, mm²
  // Per value, the elements whose centre it holds; an excluded zone only those with a part in
  // it (a piece cut along it keeps its parts outside, whatever its bounds' centre).
  std::vector<uint64_t> by_value;
  uint64_t cut = 0;  // exclude: elements cut along it
  Contour contour;   // with its arcs, where it has any
};

enum class Combine {
  mix,   // a + b = c: a cell where curds overlap takes a new value, its own colour
  keep,  // a + b = ab: every curd that survived in the cell stays visible, side by side
};
enum class Corner { bottom_left, bottom_right, top_left, top_right };
// Whether laying starts at the right edge (columns count leftwards) or at the top (rows count
// downwards).
constexpr bool from_right(Corner c) { return c == Corner::bottom_right || c == Corner::top_right; }
constexpr bool from_top(Corner c) { return c == Corner::top_left || c == Corner::top_right; }

// How the installer's sheets show the pieces: each with its ID, or (for small units such as
// bricks, setts and mosaic, where 16,000 IDs help nobody) coursed, each piece in its value's
// colour and hatch with its courses and columns numbered; automatic picks by the unit's size.
enum class InstallerSet { automatic, labelled, coursed };

// Where the layout lies in a project's projected coordinate reference system (layout.georef),
// for layout.gpkg: the datum (the layout's bottom-left corner, x = y = 0) at `easting`,
// `northing` metres of EPSG `epsg`, and its x axis turned `rotation` degrees anticlockwise from
// grid east.
struct Georef {
  int epsg = 0;
  double easting = 0, northing = 0;
  double rotation = 0;
};

// Where the layout lies in the drawing it was read from ([layout.site]): the layout's datum
// (x = y = 0) as a point of the drawing in its own units, so that outputs can be laid back onto
// the drawing at its coordinates (layout-site.dxf) and the datum stated on the sheets.
struct SiteFrame {
  std::string file;                   // the drawing, as the recipe names it
  double unit_mm = 1;                 // millimetres per drawing unit
  std::string unit_name = "mm";       // as the drawing says them: "m", "mm", "ft"
  int insunits = 4;                   // the DXF $INSUNITS code of those units
  std::array<double, 2> datum{0, 0};  // the layout's (0, 0), in drawing units
  int precision = 4;                  // decimals the drawing gives its coordinates
};

// The recipe's drawing keys: layout.png's scale, sheet and resolution, and what it overlays;
// the installer's sheets' scale, sheet and set.
struct DrawingKeys {
  double scale = 0;          // layout.png drawing scale 1 : scale; 0 picks one
  std::string paper = "A3";  // the ISO sheet a scale is picked for (drawing_sheet.h)
  double dpi = 150;
  bool stage_grid = false;       // draw lines at each stage's cell boundaries
  std::optional<Box> highlight;  // a window of cells to outline on the drawing
  double installer_scale = 0;    // 1 : installer_scale; 0 picks one
  std::string installer_paper;   // empty: `paper`
  InstallerSet installer_set = InstallerSet::automatic;
  double storey = 0;            // floor to floor, mm: level marks on the coursed sheets; 0: none
  std::vector<double> storeys;  // each storey's floor to floor from the base, where they differ
};

// The storeys' levels from the base up to `height`, mm: 0, then each floor to floor of
// `storeys` in turn where given, else every `storey`; {0} for neither.
inline std::vector<double> storey_levels(double storey, const std::vector<double>& storeys,
                                         double height) {
  std::vector<double> out{0};
  for (size_t k = 0; k < storeys.size() && out.back() + storeys[k] <= height + 1e-6; ++k)
    out.push_back(out.back() + storeys[k]);
  if (storeys.empty() && storey > 0)
    while (out.back() + storey <= height + 1e-6) out.push_back(out.back() + storey);
  return out;
}

// Ordering: spare share added to each quantity, elements per pack, and lots in laying order
// (a number of elements, e.g. a pallet, or a number of rows, e.g. a floor; 0: one lot).
struct OrderingKeys {
  double spare = 0;
  int64_t pack = 1;
  int64_t lot_size = 0;
  int64_t lot_rows = 0;
};

// A kind's own keys, copied with the spec that holds them.
class OwnKeys {
 public:
  OwnKeys() = default;
  explicit OwnKeys(std::unique_ptr<KindKeys> keys) : keys_(std::move(keys)) {}
  OwnKeys(const OwnKeys& o) : keys_(o.keys_ ? o.keys_->clone() : nullptr) {}
  OwnKeys& operator=(const OwnKeys& o) {
    keys_ = o.keys_ ? o.keys_->clone() : nullptr;
    return *this;
  }
  OwnKeys(OwnKeys&&) = default;
  OwnKeys& operator=(OwnKeys&&) = default;

  // The record as K, or nullptr when it is another kind's (or the kind has none).
  template <class K>
  const K* find() const {
    return dynamic_cast<const K*>(keys_.get());
  }
  template <class K>
  K* find() {
    return const_cast<K*>(std::as_const(*this).find<K>());
  }
  // The record as its kind's type; asking for another kind's is a programming error.
  template <class K>
  const K& as() const {
    const K* k = find<K>();
    CURDLE_CHECK(k, "a layout spec asked for another kind's keys");
    return *k;
  }
  template <class K>
  K& as() {
    return const_cast<K&>(std::as_const(*this).as<K>());
  }

 private:
  std::unique_ptr<KindKeys> keys_;
};

// The recipe's [layout] section: the keys every kind has, its kind, and its kind's own keys.
// How units are laid: a grid of rows and columns (stack or bond), or a paver's pattern
// (laying_pattern.h).
enum class LayingPattern { grid, herringbone, herringbone_45, basketweave, hexagon, hexagon_flat };

struct LayoutSpec {
  const LayoutKind* kind = nullptr;  // never null once read; set_kind sets it
  OwnKeys keys;
  void set_kind(const LayoutKind& k);  // the kind's own keys take their defaults
  template <class K>
  const K& own() const {
    return keys.as<K>();
  }
  template <class K>
  K& own() {
    return keys.as<K>();
  }

  Combine combine = Combine::mix;
  double module_w = 300, module_h = 300;  // element size (tile, panel) in mm
  double joint = 0;                       // joint between elements, mm
  // The grid moved this far back from the origin corner along x and y, so that the first
  // column and row are cut to module - shift (tile, paving, facade): how slivers are avoided.
  std::array<double, 2> shift{0, 0};
  // The narrowest cut piece allowed across x and across y, mm; 0: a third of the element that way.
  std::array<double, 2> min_cut{0, 0};
  std::vector<Zone> zones;  // tile, paving, facade
  // layout.unit: one element as the site calls it ("brick", "sett"); empty: the kind's noun.
  std::string unit;
  // layout.outline: the surface to cover, a simple polygon whose edges run along x and y, in mm
  // from the origin of `size` (which is then its bounding rectangle's far corner); empty: the
  // whole rectangle. Tile, paving, facade. Arcs are flattened within `chord_tolerance`; the
  // contour keeps them (empty where the outline has none).
  Polygon outline;
  Contour outline_contour;
  double chord_tolerance = 0.05;  // layout.chord_tolerance: how far chords stray from arcs, mm
  // layout.site: what was read from the drawing, and what the builder should know of it.
  std::string site_summary;
  std::vector<std::string> site_notes;
  std::optional<SiteFrame> site_frame;  // where the surface lies in its drawing
  // The bond: each course (row) shifted along x by this share of the element pitch from the
  // course below, counted from the origin corner: 0 stack, 1/2 stretcher or running bond, 1/3,
  // 1/4. Every element still stands for one cell; courses are cut at the ends.
  double bond = 0;
  // "english" or "flemish": bonds of headers and stretchers, laid round a building only
  // (src/building/coursing.h); empty otherwise.
  std::string header_bond;
  LayingPattern pattern = LayingPattern::grid;  // layout.pattern
  // layout.origin = "centre": the grid centred on the surface so that the cut pieces at
  // opposite edges are equal (the shift is worked out from the size); laying still starts at
  // the bottom-left.
  bool centred = false;
  std::optional<std::array<double, 2>> size;      // floor or wall, mm; default: the field's cells
  Corner origin = Corner::bottom_left;            // where cell (0, 0) and the laying order start
  std::vector<std::optional<Rgb>> value_colours;  // per value, overriding the blend (mix)
  Rgb joint_colour{150, 150, 150};
  std::vector<std::string> materials;  // per value, the product's name; empty: the curds' names
  DrawingKeys drawing;
  OrderingKeys ordering;
  std::optional<Georef> georef;  // layout.georef
};

// Where a layout came from, for title blocks and the files' metadata.
struct Provenance {
  std::string recipe;  // the design's name
  std::string description;
  uint64_t seed = 0;
  Lattice lattice;
  std::vector<CurdSpec> curds;
  Box field;  // the design's, in cells: a layout whose view is less is a segment of it
};

// What an element is, so that writers draw it without asking its layout's kind.
enum class ElementForm {
  piece,      // material laid as one or more rectangles (`shape`): whole, or cut straight
  cut_piece,  // material cut along a sloping or curved edge: its exact polygon (`outline`)
  opening,    // a hole in a sheet: round (`circle`) or merged openings (`outline`)
  object,     // a park's surface or object, in its own colour (`type`, `colour`)
  block,      // a voxel of a stack (`cell_z` its level)
};

// A one-brick wall's backing, unseen behind the face: the colour it is drawn and modelled in.
inline constexpr Rgb kBackingColour{150, 96, 72};

// What a building's unit is in its bond, for the order: a stretcher (or any whole unit on its
// face), a header through the wall, a snap header (a half unit showing as a header in a leaf),
// a queen closer, a unit cut to fit its run, or a stopped end's half unit.
enum class UnitPart : uint8_t { whole, header, snap_header, queen_closer, cut, half_bat };

struct Element {
  ElementForm form = ElementForm::piece;
  ElementId key;                    // stable and readable: kind, row and column in laying order
  std::string id;                   // key.text(), formatted once
  uint32_t value = 0;               // the overlay value of its cell
  int64_t row = 0, column = 0;      // laying order from the origin corner
  int64_t cell_x = 0, cell_y = 0;   // the field cell it stands for
  int64_t cell_z = 0;               // blocks: the voxel's level
  Rect nominal;                     // where the whole element would be
  std::vector<Rect> shape;          // what is laid: one rect, or the pieces of a cut element
  bool cut = false;                 // smaller than its stock element (edge or opening)
  double stock_w = 0, stock_h = 0;  // the whole element the piece is cut from (blocks: plan)
  std::optional<Circle> circle;     // a round opening (perforation)
  std::optional<Outline> outline;   // merged openings cut as their union (perforation, keep)
  std::string type;                 // park: the element type; empty for modules
  int sheet = -1;                   // perforation: the fabrication sheet it is cut in
  Rgb colour;                       // park: the element's own colour
  bool stands = false;              // park: an object standing on the ground (tree, bench)
  // A pattern's unit: its long side (a hexagon: a flat's normal) from x, °. A park's bench:
  // the way it faces, ° clockwise from north (+y): 0, 90, 180 or 270.
  double turn = 0;
  int corner = -1;   // a building's unit that turns the corner at the end of frames[corner]
  double depth = 0;  // a building's unit: into the wall (a header's length), mm; 0: the wall's
  UnitPart part = UnitPart::whole;  // a building's unit: its part in the bond
  double area() const;
};

struct LegendEntry {
  uint32_t value = 0;
  std::string label;
  Rgb colour;
  std::vector<Rgb> parts;  // keep mode: the colours shown side by side
  uint64_t count = 0;      // elements of this value (perforation: openings punched)
  // The first value with the same label, colour and parts: values that lay the same product
  // are one line wherever they are listed (legends, keys, hatches), as quantities.csv has them.
  uint32_t same_as = 0;
};

// A built layout: everything an exporter reads, so that writers take a Layout and nothing else.
struct Layout {
  const LayoutKind* kind = nullptr;  // what was laid; never null once built
  Provenance source;                 // recipe, seed, lattice and curds
  Combine combine = Combine::mix;
  std::string element_type;      // "tile", "paving tile", "panel"
  double width = 0, height = 0;  // mm
  double thickness = 0;          // of what is laid, mm (the kind's, for 3-D)
  double level_height = 0;       // blocks: a storey, mm; 0 for surfaces and lines
  double joint = 0;
  Rgb joint_colour;
  Corner origin = Corner::bottom_left;
  int64_t columns = 0, rows = 0;  // elements along x and y
  double module_w = 0, module_h = 0;
  std::array<double, 2> shift{0, 0};            // the grid moved back from the origin corner, mm
  double bond = 0;                              // each course's move along x, a share of the pitch
  LayingPattern pattern = LayingPattern::grid;  // units laid in a paver's pattern: outlines
  bool centred = false;                         // the grid centred on the surface
  DrawingKeys drawing;           // the drawing's scale, sheet, resolution and overlays
  OrderingKeys ordering;         // spare, packs and lots of the schedules
  std::optional<Georef> georef;  // where layout.gpkg puts it on the map; none: local metres
  std::vector<Element> elements;
  // Every hole in the surface: a façade's openings, then the excluded zones' rectangles.
  std::vector<Rect> openings;
  size_t openings_given = 0;     // the first of `openings` are the surface's own (windows, doors),
                                 // the rest excluded zones' rectangles
  std::vector<ZoneCount> zones;  // one per [[layout.zones]], in order
  // With layout.outline: the polygon, and the parts of the width x height rectangle outside it
  // (no elements; drawn as paper, not as openings).
  Polygon outline;
  Contour outline_contour;  // the outline with its arcs, where it has any
  std::string site;         // where the surface was read from (layout.site), for the report
  std::optional<SiteFrame> site_frame;  // where it lies in that drawing
  std::vector<Rect> outside;
  // What of the surface a sloping or curved outline leaves out, and excluded zones with sloping
  // or curved edges, as exact polygons (union.h's cut_away): pieces are cut along them.
  std::vector<Outline> cut_away;
  // What is not laid: openings, excluded zones and what lies outside the outline.
  std::vector<Rect> holes() const;
  std::vector<LegendEntry> legend;  // one per value
  uint64_t omitted = 0;             // cells wholly inside openings: no element
  // The open share of the surface (perforation: the openings; facade: its windows and doors),
  // and what the fabrication rules found or changed.
  double open_area = 0;
  std::vector<std::string> violations;
  bool drops_violations = false;   // openings that break a fabrication rule are dropped
  double chord_tolerance = 0.05;   // how far polygonised round openings may stray, mm
  std::vector<std::string> notes;  // what a builder should know (cut slivers, ...)
  Box view;                        // the cells laid, in field coordinates

  // What only some kinds lay: each its own record, present on their layouts alone.
  std::optional<BlockViews> block_views;        // blocks: drawn as a plan and an elevation
  std::optional<SheetFabrication> fabrication;  // perforation: the sheets cut, and their stock
  std::optional<ParkPlanting> planting;         // park: what the contractor orders
  std::optional<EnvelopeFrames> envelope;       // round a building, or along a wall's path
  // The envelope's façades (none for a flat surface), and the fabrication's sheets (none but
  // a perforated screen's).
  const std::vector<SurfaceFrame>& frames() const;
  const std::vector<FabricationSheet>& sheets() const;
  // A one-brick wall's backing behind its face; null for any other layout.
  const WallBacking* backing() const {
    return envelope && envelope->backing ? &*envelope->backing : nullptr;
  }

  // Where the edge between field cells x - 1 and x (or y - 1 and y) lies, in mm: the middle
  // of the joint, or the layout's edge.
  double cell_edge_x(int64_t cell_x) const;
  double cell_edge_y(int64_t cell_y) const;
};

}  // namespace curdle
