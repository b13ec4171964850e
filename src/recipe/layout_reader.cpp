#include "recipe/layout_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "curdle/check.h"
#include "curdle/overlay.h"
#include "curdle/text.h"
#include "kinds/registry.h"
#include "layout/builder.h"
#include "layout/drawing_sheet.h"
#include "layout/laying_pattern.h"
#include "layout/zone.h"

namespace curdle::reading {
namespace {

const std::vector<std::string> kEveryKind = {
    "kind",          "colours",  "materials",       "scale",
    "dpi",           "paper",    "spare",           "pack",
    "lot_size",      "lot_rows", "installer_scale", "installer_paper",
    "installer_set", "storey",   "georef"};

// "; the values are 0 empty, 1 dark, ..." for up to 16 values: a Markov curd's planes make
// values no state has (they never occur, yet a list gives them an entry), so they are named.
std::string value_names(const Design& design) {
  const size_t values = size_t{1} << design.curds.size();
  if (values > 16) return {};
  const std::vector<double> shares = expected_value_shares(design);
  std::string out = "; the values are";
  for (uint32_t v = 0; v < values; ++v) {
    out += (v ? ", " : " ") + std::to_string(v) + " ";
    out += shares[v] == 0 && v != 0 ? "(never occurs)" : value_label(v, design.curds);
  }
  return out;
}

// layout.materials: the product each value is laid in, one name per value, value 0 first.
void read_materials(TableReader& r, const Design& design, LayoutSpec& spec) {
  const toml::node* n = r.get("materials");
  if (!n) return;
  const size_t values = size_t{1} << design.curds.size();
  const toml::array* a = n->as_array();
  const std::string allowed = "must be " + std::to_string(values) +
                              " product names, one per value (value 0 first), e.g. "
                              "[\"Buff brick\", \"Red brick\"]" +
                              value_names(design);
  if (!a || a->size() != values) r.fail("materials", allowed);
  for (const toml::node& item : *a) {
    const auto name = item.value<std::string>();
    if (!name || name->empty() || name->size() > 200)
      r.fail("materials", allowed + "; each a non-empty name of at most 200 characters");
    if (const std::string unsafe = unsafe_text(*name); !unsafe.empty())
      r.fail_node(item, "layout.materials." + std::to_string(spec.materials.size()),
                  "holds " + unsafe + "; a product's name is one line of plain text");
    spec.materials.push_back(*name);
  }
}

// layout.origin: a corner, or (where the grid can move: tile, paving, facade) "centre".
Corner read_corner(TableReader& r, bool centre_allowed, LayoutSpec& spec) {
  const auto origin = read_string(r, "origin", "a corner").value_or("bottom-left");
  if (origin == "bottom-left") return Corner::bottom_left;
  if (origin == "bottom-right") return Corner::bottom_right;
  if (origin == "top-left") return Corner::top_left;
  if (origin == "top-right") return Corner::top_right;
  if ((origin == "centre" || origin == "center") && centre_allowed) {
    spec.centred = true;
    return Corner::bottom_left;  // laying starts there; the grid is centred (read_cut_rules)
  }
  r.fail("origin", std::string("must be \"bottom-left\", \"bottom-right\", \"top-left\" or "
                               "\"top-right\"") +
                       (centre_allowed ? ", or \"centre\" to centre the grid on the surface"
                                       : " (\"centre\" is for tile, paving and facade layouts)"));
}

std::optional<Box> read_highlight(TableReader& r) {
  const toml::node* n = r.get("highlight");
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  std::array<int64_t, 4> v{};
  bool ok = a && a->size() == 4;
  for (size_t i = 0; ok && i < 4; ++i) {
    const auto x = a->get(i)->value<int64_t>();
    ok = a->get(i)->is_integer() && x && *x >= (i < 2 ? 0 : 1) && *x <= (int64_t{1} << 40);
    if (ok) v[i] = *x;
  }
  if (!ok) r.fail("highlight", "must be [x, y, width, height] in cells, a window to outline");
  return Box{{v[0], v[1], 0}, {v[2], v[3], 1}};
}

}  // namespace

std::vector<std::string> surface_keys(const SurfaceKeys& k) {
  std::vector<std::string> keys;
  if (k.size_key != std::string("sheet")) keys.push_back("sheet");  // the paper, by name
  keys.insert(keys.end(), {"combine", "origin", "joint_colour", "stage_grid", "highlight",
                           "chord_tolerance", "site", k.module_key, k.size_key});
  if (k.joint) keys.push_back("joint");
  return keys;
}

void read_surface(TableReader& r, const SurfaceKeys& k, const Design& design, LayoutSpec& spec) {
  const auto combine = read_string(r, "combine", "\"mix\" or \"keep\"").value_or("mix");
  if (combine == "mix")
    spec.combine = Combine::mix;
  else if (combine == "keep")
    spec.combine = Combine::keep;
  else
    r.fail("combine",
           "must be \"mix\" (a + b = c) or \"keep\" (a + b = ab), not \"" + combine + "\"");
  if (const auto module = read_mm_pair(r, k.module_key))
    spec.module_w = (*module)[0], spec.module_h = (*module)[1];
  spec.joint = k.joint ? read_mm(r, "joint", 0, 0) : 0;
  if (spec.joint >= std::min(spec.module_w, spec.module_h))
    r.fail("joint", std::string("must be narrower than the ") + k.module_key + " (" +
                        std::to_string(static_cast<int>(std::min(spec.module_w, spec.module_h))) +
                        " mm)");
  spec.chord_tolerance = read_mm(r, "chord_tolerance", 0.05, 0);
  // Finer than a micrometre no cutter follows, and the polygons would grow without bound.
  if (spec.chord_tolerance < 0.001 || spec.chord_tolerance > 100)
    r.fail("chord_tolerance",
           "must be from 0.001 mm (a micrometre) to 100 mm: how far the chords that cut pieces "
           "along an arc or circle may stray from it, e.g. 0.05");
  // An outline (typed, or read from the site's drawing) can stand for the size: its bounding
  // rectangle.
  spec.size = read_mm_pair(
      r, k.size_key, k.size_required && !r.get("outline") && !r.get("site") && !r.get("building"));
  read_site(r, design, spec);
  read_outline(r, spec);
  spec.origin = read_corner(r, k.grid_moves, spec);
  read_value_colours(r, design, spec);
  if (const auto colour = read_colour(r, "joint_colour")) spec.joint_colour = *colour;
  spec.drawing.stage_grid = read_bool(r, "stage_grid", false);
  spec.drawing.highlight = read_highlight(r);
  read_drawing_scale(r, spec);
}

namespace {

// layout.bond: how far each course moves along from the one below.
void read_bond(TableReader& r, LayoutSpec& spec) {
  const auto bond = read_string(r, "bond", "a bond").value_or("stack");
  if (bond == "stack")
    spec.bond = 0;
  else if (bond == "half" || bond == "stretcher" || bond == "running")
    spec.bond = 0.5;
  else if (bond == "third")
    spec.bond = 1.0 / 3;
  else if (bond == "quarter")
    spec.bond = 0.25;
  else if ((bond == "english" || bond == "flemish") && r.get("building"))
    spec.header_bond = bond, spec.bond = 0.5;
  else if (bond == "english" || bond == "flemish")
    r.fail("bond", fmt::format("\"{}\" bond lays headers through the wall, round a building "
                               "([layout.building]) only; a flat surface takes \"stack\", "
                               "\"half\", \"third\" or \"quarter\"",
                               bond));
  else
    r.fail("bond",
           "must be \"stack\" (joints in line), \"half\" (stretcher or running bond), "
           "\"third\" or \"quarter\": the share of an element each course moves along from the "
           "one below; round a building also \"english\" or \"flemish\"");
  if (spec.bond > 0 && spec.combine == Combine::keep)
    r.fail("bond", "needs combine = \"mix\": kept curds are drawn as stripes of a stacked grid");
}

// layout.pattern: a paver's pattern instead of the grid (laying_pattern.h), with the tile's
// proportions it needs.
void read_pattern(TableReader& r, LayoutSpec& spec) {
  const auto name = read_string(r, "pattern", "a laying pattern");
  if (!name) return;
  const auto pattern = pattern_named(*name);
  if (!pattern)
    r.fail("pattern",
           "must be \"grid\" (rows and columns, with layout.bond), \"herringbone\" (90°), "
           "\"herringbone-45\", \"basketweave\", \"hexagon\" (pointy top) or "
           "\"hexagon-flat\"");
  spec.pattern = *pattern;
  if (spec.pattern == LayingPattern::grid) return;
  if (!spec.size)
    r.fail("pattern",
           "needs the surface's size in millimetres: a pattern is laid over a floor "
           "or wall, not over the field's cells");
  if (spec.bond > 0)
    r.fail("bond", fmt::format("cannot be given with pattern = \"{}\": the pattern sets where "
                               "every unit goes",
                               *name));
  if (spec.combine == Combine::keep)
    r.fail("pattern", "needs combine = \"mix\": kept curds are drawn as stripes of a grid");
  if (spec.centred) r.fail("origin", "must be a corner with a pattern: laying starts there");
  const double w = spec.module_w, h = spec.module_h, j = spec.joint;
  switch (spec.pattern) {
    case LayingPattern::herringbone:
    case LayingPattern::herringbone_45:
      if (std::fabs(w - (2 * h + j)) > 0.5)
        r.fail("pattern", fmt::format("herringbone needs a unit two widths and a joint long: "
                                      "{:g} mm wide with {:g} mm joints is {:g} x {:g} mm, not "
                                      "{:g} x {:g}",
                                      h, j, 2 * h + j, h, w, h));
      break;
    case LayingPattern::basketweave:
      if (basketweave_units(w, h, j) == 0)
        r.fail("pattern", fmt::format("basketweave needs a unit n widths and n - 1 joints long, "
                                      "n from 2 to 4, so that n of them make a square: {:g} mm "
                                      "wide with {:g} mm joints is {:g}, {:g} or {:g} mm long, "
                                      "not {:g}",
                                      h, j, 2 * h + j, 3 * h + 2 * j, 4 * h + 3 * j, w));
      break;
    case LayingPattern::hexagon:
    case LayingPattern::hexagon_flat:
      if (std::fabs(w - h) > 1e-9)
        r.fail("pattern", fmt::format("a hexagon's tile is given square, its side the width "
                                      "across the flats: [{:g}, {:g}], not [{:g}, {:g}]",
                                      w, w, w, h));
      break;
    case LayingPattern::grid:
      break;
  }
}

// layout.min_cut: one width for both ways, or [across x, across y] (a brick's 70 mm along the
// course and 22 mm up it), each at most the element that way.
void read_min_cut(TableReader& r, LayoutSpec& spec) {
  const toml::node* n = r.get("min_cut");
  if (!n) return;
  const std::string allowed = fmt::format(
      "must be millimetres, one number for both ways or [across x, across y], each from 0 up to "
      "the element ({:g} x {:g} mm); e.g. [70, 22] for bricks cut to at least 70 mm long and "
      "22 mm high; 0 or absent: a third of the element",
      spec.module_w, spec.module_h);
  const toml::array* a = n->as_array();
  if (a && a->size() != 2) r.fail("min_cut", allowed);
  for (size_t i = 0; i < 2; ++i) {
    const auto v = finite_number(a ? a->get(i) : n);
    if (!v || *v < 0 || *v > (i ? spec.module_h : spec.module_w)) r.fail("min_cut", allowed);
    spec.min_cut[i] = *v;
  }
}

}  // namespace

// layout.min_cut and layout.shift: the narrowest cut piece, and the grid moved to avoid slivers.
void read_cut_rules(TableReader& r, const Design& design, LayoutSpec& spec) {
  read_bond(r, spec);
  read_pattern(r, spec);
  read_zones(r, design, spec);
  const bool sloping_zone = std::any_of(spec.zones.begin(), spec.zones.end(), [](const Zone& z) {
    return z.rule == ZoneRule::exclude && z.rects.empty();
  });
  if (spec.combine == Combine::keep &&
      (sloping_zone || (!spec.outline.empty() && !as_rectangles(spec.outline))))
    r.fail(sloping_zone ? "zones" : "outline",
           "has sloping or curved edges, which need combine = \"mix\": kept curds are drawn as "
           "stripes of whole rectangles");
  read_min_cut(r, spec);
  const std::string unit_allowed =
      "must be the name of one element as the site calls it, 1 to 40 characters, e.g. "
      "\"brick\" or \"sett\" (notes and keys add an s for more than one)";
  if (const auto unit = read_name(r, "unit", unit_allowed)) {
    if (unit->empty() || unit->size() > 40) r.fail("unit", unit_allowed);
    spec.unit = *unit;
  }
  const toml::node* n = r.get("shift");
  if (n && spec.pattern != LayingPattern::grid)
    r.fail("shift", "cannot be given with a pattern: laying starts at the origin corner");
  if (spec.centred) {
    if (n) r.fail("shift", "cannot be given with origin = \"centre\", which works the shift out");
    if (spec.size)
      for (int i = 0; i < 2; ++i)
        spec.shift[static_cast<size_t>(i)] = centring_shift(
            (*spec.size)[static_cast<size_t>(i)], i ? spec.module_h : spec.module_w, spec.joint);
    return;
  }
  if (!n) return;
  const toml::array* a = n->as_array();
  const std::string allowed = fmt::format(
      "must be [x, y] in millimetres, each from 0 up to less than the element ({:g} "
      "x {:g} mm): how far the grid moves back from the origin corner",
      spec.module_w, spec.module_h);
  if (!a || a->size() != 2) r.fail("shift", allowed);
  for (size_t i = 0; i < 2; ++i) {
    const auto v = finite_number(a->get(i));
    const double module = i ? spec.module_h : spec.module_w;
    if (!v || *v < 0 || *v >= module) r.fail("shift", allowed);
    spec.shift[i] = *v;
  }
}

namespace {

// layout.installer_scale, installer_paper, installer_set and storey: the installer's sheets.
void read_installer_keys(TableReader& r, DrawingKeys& drawing) {
  if (const auto paper = read_string(r, "installer_paper", "an ISO sheet name such as \"A3\"")) {
    if (!paper_sheet(*paper))
      r.fail("installer_paper",
             "must be \"A0\", \"A1\", \"A2\", \"A3\" or \"A4\": the sheet the installer's "
             "sheets are drawn on");
    drawing.installer_paper = *paper;
  }
  if (const toml::node* scale = r.get("installer_scale")) {
    // A scale's N, not a length: any other number or text gets the scale's own message.
    const double n = finite_number(scale).value_or(0);
    const auto& scales = standard_scales();
    if (std::find(scales.begin(), scales.end(), n) == scales.end() || n > 1000)
      r.fail("installer_scale",
             "must be a standard scale's N of 1 : N up to 1000 (1, 2, 5, 10, 20, 25, 50, 100, "
             "200, 250, 500 or 1000)");
    drawing.installer_scale = n;
  }
  drawing.storey = read_mm(r, "storey", 0, 1);
  const auto set = read_string(r, "installer_set", "a kind of set");
  if (!set || *set == "automatic")
    drawing.installer_set = InstallerSet::automatic;
  else if (*set == "labelled" || *set == "labeled")
    drawing.installer_set = InstallerSet::labelled;
  else if (*set == "coursed")
    drawing.installer_set = InstallerSet::coursed;
  else
    r.fail("installer_set",
           "must be \"labelled\" (every piece with its ID), \"coursed\" (pieces in colour and "
           "hatch, courses and columns numbered, for bricks, setts and mosaic) or \"automatic\" "
           "(coursed where the units are at most 300 mm long)");
}

}  // namespace

void read_drawing_scale(TableReader& r, LayoutSpec& spec) {
  // layout.paper, or layout.sheet written as a name where the sheet is not the kind's surface.
  const bool sheet_is_paper = spec.kind->ground() != Ground::sheet && r.get("sheet");
  const char* key = sheet_is_paper ? "sheet" : "paper";
  if (const auto paper = read_string(r, key, "an ISO sheet name such as \"A3\"")) {
    if (!paper_sheet(*paper))
      r.fail(key,
             "must be \"A0\", \"A1\", \"A2\", \"A3\" or \"A4\": the sheet layout.png is "
             "scaled to fit");
    spec.drawing.paper = *paper;
  }
  spec.drawing.scale = read_mm(r, "scale", 0, 1);
  spec.drawing.dpi = read_mm(r, "dpi", 150, 10);
  if (spec.drawing.dpi > 1200) r.fail("dpi", "must be from 10 to 1200");
  read_installer_keys(r, spec.drawing);
  if (spec.drawing.installer_set == InstallerSet::coursed && !spec.kind->laid_in_courses())
    r.fail("installer_set",
           "\"coursed\" is for elements laid in courses (tile, paving, facade, "
           "park); a " +
               std::string(spec.kind->name()) + " layout's sheets are \"labelled\"");
}

namespace {

// layout.georef: where layout.gpkg puts the layout in the project's projected CRS. Whether GDAL
// knows the EPSG code is the GeoPackage writer's to say; here, that it can be one.
void read_georef(TableReader& r, LayoutSpec& spec) {
  if (!r.get("georef")) return;
  const toml::table* t = read_table(r, "georef");
  if (!t)
    r.fail("georef", "must be a table: [layout.georef] with epsg, easting, northing, rotation");
  TableReader g(*t, r.key_path("georef"), r.source(),
                {"epsg", "easting", "northing", "rotation", "from"});
  if (spec.kind->upright())
    r.fail("georef", std::string("places a plan on the map; a ") + std::string(spec.kind->name()) +
                         " layout is an elevation, drawn in its wall's own metres");
  Georef geo;
  geo.epsg = static_cast<int>(read_int(g, "epsg", 0, 1024, 32767, true));
  auto coordinate = [&](const char* key, double lo, double hi, const char* what) {
    const toml::node* n = g.get(key);
    if (!n) return 0.0;
    const auto v = finite_number(n);
    if (!v || *v < lo || *v > hi) g.fail(key, what);
    return *v;
  };
  geo.easting = coordinate("easting", -1e8, 1e8,
                           "must be the datum's easting in the CRS's metres, a finite number "
                           "within 100,000 km");
  geo.northing = coordinate("northing", -1e8, 1e8,
                            "must be the datum's northing in the CRS's metres, a finite number "
                            "within 100,000 km");
  geo.rotation = coordinate("rotation", -360, 360,
                            "must be the layout's x axis in degrees anticlockwise from grid east, "
                            "from -360 to 360");
  // from = "site": the datum's coordinates as the site drawing gives them, nothing retyped.
  if (g.get("from")) {
    if (read_string(g, "from", "\"site\"").value_or("") != "site")
      g.fail("from",
             "must be \"site\": the datum's easting and northing are its coordinates in "
             "[layout.site]'s drawing, drawn in the CRS of epsg");
    if (g.get("easting") || g.get("northing") || g.get("rotation"))
      g.fail("from",
             "takes easting and northing from the site drawing (its axes are the grid's); "
             "give from or easting, northing and rotation, not both");
    if (!spec.site_frame)
      g.fail("from",
             "takes the datum from [layout.site]'s DXF drawing, and this recipe reads "
             "none");
    geo.easting = spec.site_frame->datum[0] * spec.site_frame->unit_mm / 1000;
    geo.northing = spec.site_frame->datum[1] * spec.site_frame->unit_mm / 1000;
    if (std::fabs(geo.easting) > 1e8 || std::fabs(geo.northing) > 1e8)
      g.fail("from",
             "gives a datum beyond 100,000 km of the CRS's origin: is the drawing's "
             "unit right?");
  }
  g.report_unused("is not a key of layout.georef (epsg, easting, northing, rotation, from)");
  spec.georef = geo;
}

}  // namespace

std::vector<std::string> layout_keys(const LayoutKind& kind) {
  std::vector<std::string> keys = kEveryKind;
  const std::vector<std::string> own = kind.keys();
  keys.insert(keys.end(), own.begin(), own.end());
  return keys;
}

std::optional<LayoutSpec> read_layout(TableReader& top, Design& design, bool field_given) {
  const toml::table* t = read_table(top, "layout");
  if (!t) return std::nullopt;
  std::string name = "tile";
  if (const toml::node* n = t->get("kind")) {
    if (!n->is_string()) top.fail_node(*n, "layout.kind", "must be a string such as \"paving\"");
    name = *n->value<std::string>();
  }
  const LayoutKind* kind = find_layout_kind(name);
  if (!kind)
    top.fail_node(*t->get("kind"), "layout.kind",
                  "unknown element kind \"" + name + "\"; allowed: " + layout_kind_names());
  const std::vector<std::string> keys = layout_keys(*kind);
  TableReader r(*t, "layout", top.source(), keys);

  LayoutSpec spec;
  spec.set_kind(*kind);
  r.get("kind");  // read above
  read_ordering(r, spec);
  read_materials(r, design, spec);
  const int dimension = kind->dimension();
  if (design.lattice.dimension != dimension)
    r.fail("kind", "a " + name + " layout needs a " + std::to_string(dimension) +
                       "-D lattice; this one is " + std::to_string(design.lattice.dimension) +
                       "-D");
  kind->read(r, design, spec, field_given);
  read_georef(r, spec);  // after the kind's keys: from = "site" takes [layout.site]'s datum
  r.report_unused("is not read by a " + std::string(kind->name()) + " layout");
  // A key the kind lists but its reader never asks for would pass unread: a programming error.
  const auto unread = r.never_asked();
  CHECK(unread.empty(), "the " + std::string(kind->name()) +
                            " kind lists keys its reader never asks for: " + join(unread));
  return spec;
}

void size_field(TableReader& r, const std::string& size_key, Design& design, const LayoutSpec& spec,
                bool field_given) {
  if (!spec.size) return;
  const auto cells = elements_to_cover(spec);
  // A larger field is a curd from which a segment of `cells` becomes the floor or wall.
  if (field_given && (design.field.size[0] < cells[0] || design.field.size[1] < cells[1]))
    r.fail(size_key, "needs " + std::to_string(cells[0]) + " x " + std::to_string(cells[1]) +
                         " elements but field.cells is " + std::to_string(design.field.size[0]) +
                         " x " + std::to_string(design.field.size[1]) +
                         "; leave field.cells out, or make it at least that large");
  if (!field_given) {
    design.field.size[0] = cells[0];
    design.field.size[1] = cells[1];
  }
}

// Ordering: the spare share, pack size and lots of the schedules.
void read_ordering(TableReader& r, LayoutSpec& spec) {
  if (const toml::node* n = r.get("spare")) {
    const auto v = finite_number(n);
    if (!v || !std::isfinite(*v) || *v < 0 || *v > 10)
      r.fail("spare", "must be a share from 0 to 10, e.g. 0.05 for 5 % spare; not negative");
    spec.ordering.spare = *v;
  }
  OrderingKeys& o = spec.ordering;
  o.pack = read_int(r, "pack", 1, 1, 1000000);
  o.lot_size = read_int(r, "lot_size", 0, 0, INT64_MAX);
  o.lot_rows = read_int(r, "lot_rows", 0, 0, INT64_MAX);
  if (o.lot_size && o.lot_rows)
    r.fail("lot_rows", "give lots either by size (lot_size) or by rows (lot_rows), not both");
}

// layout.colours: exactly one "#rrggbb" per value, value 0 first.
void read_value_colours(TableReader& r, const Design& design, LayoutSpec& spec) {
  const size_t values = size_t{1} << design.curds.size();
  if (const toml::node* n = r.get("colours")) {
    const toml::array* a = n->as_array();
    if (!a) r.fail("colours", "must be an array of colours \"#rrggbb\", one per value");
    if (a->size() < values)
      r.fail("colours", "gives " + std::to_string(a->size()) + " colours for " +
                            std::to_string(values) + " values (2^" +
                            std::to_string(design.curds.size()) +
                            " curds); give one per value, value 0 first" + value_names(design));
    if (a->size() > values)
      r.fail("colours", "gives " + std::to_string(a->size()) + " colours but there are only " +
                            std::to_string(values) + " values");
    for (size_t v = 0; v < a->size(); ++v) {
      const auto text = a->get(v)->value<std::string>();
      const auto colour = text ? parse_colour(*text) : std::nullopt;
      if (!colour)
        r.fail_node(*a->get(v), "layout.colours." + std::to_string(v),
                    "must be a colour written \"#rrggbb\"");
      spec.value_colours.push_back(colour);
    }
  }
}

}  // namespace curdle::reading
