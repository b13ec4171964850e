// [layout] of kind "perforation": one opening per curd, the sheet and the fabrication rules.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "curdle/markov.h"
#include "kinds/perforation.h"
#include "recipe/layout_reader.h"

namespace curdle::reading {
namespace {

// layout.punches: the diameters the tools cut; every hole's diameter must be one of them.
void read_punches(TableReader& r, LayoutSpec& spec) {
  const toml::node* n = r.get("punches");
  if (!n) return;
  const toml::array* a = n->as_array();
  const std::string allowed =
      "must be the punches' diameters in millimetres, e.g. [16, 22.6, 27.7], each above 0";
  if (!a || a->empty() || a->size() > 100) r.fail("punches", allowed + ", at most 100");
  std::vector<double>& punches = spec.own<PerforationKeys>().punches;
  for (const toml::node& item : *a) {
    const auto d = finite_number(&item);
    if (!d || *d <= 0 || *d > 1e7) r.fail("punches", allowed);
    punches.push_back(*d);
  }
  std::sort(punches.begin(), punches.end());
  punches.erase(std::unique(punches.begin(), punches.end()), punches.end());
  for (size_t i = 0; i < spec.own<PerforationKeys>().holes.size(); ++i) {
    const double d = spec.own<PerforationKeys>().holes[i].diameter;
    if (std::none_of(punches.begin(), punches.end(),
                     [&](double p) { return std::fabs(p - d) < 1e-9; }))
      r.fail("punches", "has no punch for layout.holes." + std::to_string(i) + " (diameter " +
                            fmt::format("{:g}", d) +
                            " mm); every hole's diameter must be one of the punches");
  }
}

// layout.open_area: [min, max] share of each sheet that must be open.
void read_open_area(TableReader& r, LayoutSpec& spec) {
  const toml::node* n = r.get("open_area");
  if (!n) return;
  const toml::array* a = n->as_array();
  double lo = 0, hi = 0;
  bool ok = a && a->size() == 2;
  if (ok) {
    const auto l = finite_number(a->get(0)), h = finite_number(a->get(1));
    ok = l && h;
    if (ok) lo = *l, hi = *h;
  }
  if (!ok || lo < 0 || hi > 1 || lo > hi)
    r.fail("open_area",
           "must be [min, max], shares of each sheet from 0 to 1, min not above max; e.g. "
           "[0.15, 0.30] for 15 % to 30 % open");
  spec.own<PerforationKeys>().open_area = std::array<double, 2>{lo, hi};
}

}  // namespace

void read_perforation(TableReader& r, const Design& design, LayoutSpec& spec) {
  spec.own<PerforationKeys>().thickness = read_mm(r, "thickness", 0, 0, true);
  if (spec.own<PerforationKeys>().thickness <= 0) r.fail("thickness", "must be above 0 mm");
  spec.own<PerforationKeys>().min_diameter = read_mm(r, "min_diameter", 0, 0);
  spec.own<PerforationKeys>().min_bridge = read_mm(r, "min_bridge", 0, 0);
  spec.own<PerforationKeys>().edge_margin = read_mm(r, "edge_margin", 0, 0);
  spec.own<PerforationKeys>().chord_tolerance = spec.chord_tolerance;  // read with the surface
  const auto fix = read_string(r, "fix", "\"none\" or \"drop\"").value_or("none");
  if (fix == "none")
    spec.own<PerforationKeys>().fix = HoleFix::none;
  else if (fix == "drop")
    spec.own<PerforationKeys>().fix = HoleFix::drop;
  else
    r.fail("fix",
           "must be \"none\" (report only) or \"drop\" (drop the openings that break a rule)");
  const toml::node* n = r.get("holes");
  if (!n)
    r.fail(
        "holes",
        "is required: one {diameter, offset} per curd, e.g. [{diameter = 20, offset = [-10, 0]}]");
  const toml::array* a = n->as_array();
  if (!a || a->size() != curd_members(design.curds).size())
    r.fail("holes", "must give one {diameter, offset} per curd, and per state of a Markov curd: " +
                        std::to_string(curd_members(design.curds).size()) + " curds, " +
                        std::to_string(a ? a->size() : 0) + " holes");
  for (size_t i = 0; i < a->size(); ++i) {
    const std::string path = "layout.holes." + std::to_string(i);
    const toml::table* h = a->get(i)->as_table();
    if (!h) r.fail_node(*a->get(i), path, "must be a table {diameter = 20, offset = [0, 0]}");
    TableReader hr(*h, path, r.source(), {"diameter", "offset"});
    HoleSpec hole;
    hole.diameter = read_mm(hr, "diameter", 0, 0, true);
    if (hole.diameter <= 0) hr.fail("diameter", "must be above 0 mm");
    if (const auto off = hr.get("offset")) {
      const toml::array* o = off->as_array();
      const auto x = o && o->size() == 2 ? finite_number(o->get(0)) : std::nullopt;
      const auto y = o && o->size() == 2 ? finite_number(o->get(1)) : std::nullopt;
      if (!x || !y) hr.fail("offset", "must be [x, y] in millimetres from the cell centre");
      hole.offset_x = *x, hole.offset_y = *y;
    }
    if (std::fabs(hole.offset_x) + hole.diameter / 2 > spec.module_w / 2 + 1e-9 ||
        std::fabs(hole.offset_y) + hole.diameter / 2 > spec.module_h / 2 + 1e-9)
      r.fail_node(
          *a->get(i), path,
          "a hole of " + std::to_string(hole.diameter) + " mm at that offset does not fit in its " +
              std::to_string(static_cast<int>(spec.module_w)) + " x " +
              std::to_string(static_cast<int>(spec.module_h)) +
              " mm cell; holes must lie inside their cells (smaller, or nearer the centre)");
    spec.own<PerforationKeys>().holes.push_back(hole);
  }
  read_punches(r, spec);
  read_open_area(r, spec);
  if (auto m = read_name(r, "sheet_material", "the sheets' material, e.g. \"aluminium 5005\""))
    spec.own<PerforationKeys>().sheet_material = *m;
  spec.own<PerforationKeys>().sheet_size = read_mm_pair(r, "sheet_size");
  if (spec.own<PerforationKeys>().sheet_size) {
    double largest = 0;
    for (const HoleSpec& h : spec.own<PerforationKeys>().holes)
      largest = std::max(largest, h.diameter);
    if ((*spec.own<PerforationKeys>().sheet_size)[0] <
            largest + 2 * spec.own<PerforationKeys>().edge_margin ||
        (*spec.own<PerforationKeys>().sheet_size)[1] <
            largest + 2 * spec.own<PerforationKeys>().edge_margin)
      r.fail("sheet_size",
             "a sheet must hold the largest opening (" + std::to_string(static_cast<int>(largest)) +
                 " mm) within its margins (2 x " +
                 std::to_string(static_cast<int>(spec.own<PerforationKeys>().edge_margin)) +
                 " mm); give a larger sheet_size");
  }
}

void read_perforated_building(TableReader& r, LayoutSpec& spec) {
  for (const char* key : {"outline", "site", "sheet"})
    if (r.get(key))
      r.fail(key,
             "does not go with [layout.building]: the screen is the building's envelope, as "
             "high as layout.building.height and as long as its plan or path");
  if (spec.origin != Corner::bottom_left)
    r.fail("origin", "a screen on a building starts at its start corner, bottom left");
  // What a brick wall is made of, or openings in it, a screen of sheets does not have yet.
  const toml::table* building = r.get("building")->as_table();
  if (!building)
    r.fail("building", "must be a table: [layout.building] with plan (or path) and height");
  const toml::table& t = *building;
  for (const char* key : {"wall", "backing", "depth", "phase", "openings", "windows", "elevations",
                          "coursed_openings"})
    if (const toml::node* n = t.get(key))
      r.fail_node(*n, r.key_path("building") + "." + key,
                  std::string("is not a key of a perforated screen on a building: it takes plan "
                              "(or path, or site), height, heights, storey, storeys, base, start "
                              "and arcs; its sheet is layout.thickness deep") +
                      (std::string_view(key) == "openings" || std::string_view(key) == "windows"
                           ? ", and it has no windows or doors"
                           : ""));
  if (const toml::node* arcs = t.get("arcs"); arcs && arcs->value<std::string>() == "chords")
    r.fail_node(*arcs, r.key_path("building.arcs"),
                "a perforated sheet on an arc is rolled to it: arcs = \"bent\" (the default "
                "for a screen); for flat sheets on chords, give the plan the chords as straight "
                "edges");
  PerforationKeys& keys = spec.own<PerforationKeys>();
  ReadBuilding read = read_building(r, spec, true);
  keys.building = std::move(read.keys);
  keys.envelope = std::move(read.envelope);
  keys.envelope->depth = keys.thickness;
  if (!keys.building->site_summary.empty()) spec.site_summary = keys.building->site_summary;
  spec.size = std::array<double, 2>{keys.envelope->length, keys.envelope->height};
}

}  // namespace curdle::reading
