// [layout.building]: plan = [[x, y], [x, y, bulge], ...] (closed, a building) or path = [...]
// (open, a free-standing wall), height, storey, base, depth, start, coursed_openings,
// [[layout.building.openings]] (facade, rect, type, replaces) and [layout.building.windows]
// (size, every, clear, sill, omit).
#include <fmt/format.h>

#include <cmath>

#include "building/coursing.h"
#include "curdle/error.h"
#include "layout/contour.h"
#include "recipe/layout_reader.h"

namespace curdle::reading {
namespace {

constexpr size_t kMostPlanVertices = 10000;
constexpr size_t kMostOpenings = 10000;

// An open path's vertices, each [x, y] or [x, y, bulge], within 10 km.
Contour read_path(TableReader& r) {
  return read_vertices(
      r, "path",
      "must be 2 to 10000 points [[x, y], ...] in millimetres along the wall's outer face, "
      "within 10 km; [x, y, bulge] makes the edge to the next point an arc (bulge = tan(angle / "
      "4), positive anticlockwise), or an arc after a point by its centre: { centre = [x, y], "
      "sweep = degrees } or { centre = [x, y], length = mm along it }, and radius = mm as a check",
      2, kMostPlanVertices, 1e7);
}

BuildingOpening read_opening(TableReader& o, size_t index) {
  BuildingOpening b;
  if (const auto name = read_string(o, "replaces", "a window of the rule by name (\"W-5\")")) {
    if (name->size() < 3 || name->rfind("W-", 0) != 0)
      o.fail("replaces", "must name a window of the rule as the outputs do: \"W-5\"");
    b.replaces = *name;
  }
  const toml::node* f = o.get("facade");
  if (const auto i = f ? f->value<int64_t>() : std::nullopt; i && *i >= 0)
    b.facade = std::to_string(*i);
  else if (const auto s = f ? f->value<std::string>() : std::nullopt; s && !s->empty())
    b.facade = *s;
  else if (b.replaces.empty() || f)
    o.fail("facade", fmt::format("opening {} needs facade = its façade's index (the plan edge "
                                 "from that vertex) or its name (\"S\", \"E2\"); one that "
                                 "replaces a window may leave it out (the window's façade)",
                                 index));
  const toml::array* a = o.get("rect") ? o.get("rect")->as_array() : nullptr;
  std::array<double, 4> v{};
  bool ok = a && a->size() == 4;
  for (size_t k = 0; ok && k < 4; ++k) {
    const auto x = finite_number(a->get(k));
    ok = x && *x <= 1e7 && (k < 2 ? *x >= 0 : *x > 0);
    if (ok) v[k] = *x;
  }
  if (!ok)
    o.fail("rect",
           "must be [x, y, width, height] in millimetres, x along the façade from its start and "
           "y up from the base, sizes above 0");
  b.rect = Rect{v[0], v[1], v[2], v[3]};
  b.type = read_string(o, "type", "\"window\" or \"door\"").value_or("window");
  if (b.type != "window" && b.type != "door") o.fail("type", "must be \"window\" or \"door\"");
  o.report_unused("is not a key of an opening (facade, rect, type, replaces)");
  return b;
}

WindowRule read_windows(TableReader& w) {
  WindowRule rule;
  const auto size = read_mm_pair(w, "size", true);
  rule.size = *size;
  rule.every = read_mm(w, "every", 0, 1, true);
  if (rule.every < rule.size[0])
    w.fail("every", "must be at least the window's width: windows stand apart");
  rule.clear = read_mm(w, "clear", 0, 0);
  rule.sill = read_mm(w, "sill", 0, 0);
  if (const toml::node* n = w.get("omit")) {
    const toml::array* a = n->as_array();
    const char* allowed = "must be a list of the rule's windows by name: [\"W-3\", \"W-17\"]";
    if (!a || a->size() > 10000) w.fail("omit", allowed);
    for (const toml::node& item : *a) {
      const auto name = item.value<std::string>();
      if (!name || name->size() < 3 || name->size() > 32 || name->rfind("W-", 0) != 0)
        w.fail("omit", allowed);
      rule.omit.push_back(*name);
    }
  }
  w.report_unused("is not a key of layout.building.windows (size, every, clear, sill, omit)");
  return rule;
}

}  // namespace

// storeys: each storey's floor to floor from the base where they differ (a taller ground
// floor), instead of one `storey`.
void read_storeys(TableReader& r, BuildingKeys& b) {
  const toml::node* n = r.get("storeys");
  if (!n) return;
  if (b.storey > 0) r.fail("storeys", "cannot be given with `storey`: give one or the other");
  const toml::array* a = n->as_array();
  const std::string allowed =
      "must be each storey's floor-to-floor height from the base, in mm, each at least 1000, "
      "together at most the wall's height";
  if (!a || a->empty() || a->size() > 1000) r.fail("storeys", allowed);
  double sum = 0;
  for (const toml::node& item : *a) {
    const auto h = finite_number(&item);
    if (!h || *h < 1000 || *h > 1e6) r.fail("storeys", allowed);
    b.storeys.push_back(*h);
    sum += *h;
  }
  if (sum > b.height + 1e-6)
    r.fail("storeys",
           fmt::format("add up to {:g} mm, more than the wall's height ({:g} mm)", sum, b.height));
}

// wall = "half-brick", "cavity" or "one-brick", and a one-brick wall's backing material.
void read_wall(TableReader& r, BuildingKeys& b) {
  if (const auto wall = read_string(r, "wall", "what the wall is")) {
    if (*wall != "half-brick" && *wall != "one-brick" && *wall != "cavity")
      r.fail("wall",
             "must be \"half-brick\" (a leaf of the face alone; English and Flemish headers are "
             "snap headers), \"cavity\" (a cavity wall's outer leaf, likewise) or \"one-brick\" "
             "(solid, a unit's length thick: headers run through and backing units stand behind "
             "the rest)");
    b.wall = *wall;
  }
  if (const auto backing = read_string(r, "backing", "the backing units' material")) {
    if (b.wall != "one-brick")
      r.fail("backing",
             "is the material behind the face of a one-brick wall (wall = "
             "\"one-brick\"); a half-brick or cavity leaf has none");
    if (backing->empty() || backing->size() > 200)
      r.fail("backing", "must be the backing units' material, 1 to 200 characters");
    b.backing = *backing;
  }
}

ReadBuilding read_building(TableReader& layout, const LayoutSpec& spec, bool bent_by_default) {
  const toml::table* t = read_table(layout, "building");
  if (!t)
    layout.fail("building", "must be a table: [layout.building] with plan (or path) and height");
  TableReader r(*t, layout.key_path("building"), layout.source(),
                {"plan", "path", "site", "height", "storey", "storeys", "base", "depth", "start",
                 "phase", "coursed_openings", "arcs", "openings", "windows", "elevations",
                 "heights", "wall", "backing"});
  BuildingKeys b;
  const bool drawn = r.get("site");
  const bool plan = r.get("plan") || drawn, path = r.get("path");
  if (drawn && r.get("plan"))
    r.fail("plan",
           "is given by [layout.building.site]'s drawing; give plan or the drawing, not both");
  if (plan == path)
    r.fail(plan ? "path" : "plan",
           "a building needs one of plan = [[x, y], ...] (closed, anticlockwise), "
           "[layout.building.site] (its plan from a drawing's layer) or path = [[x, y], ...] (a "
           "free-standing wall)");
  double model_height = 0;  // mm, where the plan is a massing model's node
  if (drawn) b.plan = read_site_plan(r, spec, b.site_summary, model_height);
  if (plan && !drawn) b.plan = read_contour(r, "plan", spec.chord_tolerance).contour;
  if (plan && !drawn && b.plan.empty()) {  // no arcs: read_contour keeps the polygon only
    b.plan = read_vertices(r, "plan", "must be the plan's corners", 3, kMostPlanVertices, 1e300);
    if (b.plan.size() > 2 && b.plan.front().x == b.plan.back().x &&
        b.plan.front().y == b.plan.back().y)
      b.plan.pop_back();
  }
  for (const ContourVertex& v : b.plan)
    if (std::fabs(v.x) > 1e7 || std::fabs(v.y) > 1e7)
      r.fail("plan",
             "has a vertex beyond 10 km: give the plan in millimetres from a datum near it");
  if (path) b.path = read_path(r);
  // A massing model says how high the building stands; the recipe may say otherwise.
  b.height = read_mm(r, "height", std::round(model_height), 1, !(model_height >= 1));
  if (model_height >= 1 && std::fabs(b.height - model_height) > 0.5)
    b.site_summary += fmt::format(
        "; the model stands {:.0f} mm high, and the recipe's height of "
        "{:g} mm is laid",
        model_height, b.height);
  if (const toml::node* n = r.get("heights")) {
    const toml::array* a = n->as_array();
    const std::string allowed =
        "must be one height a plan edge, in the plan's order, each in mm up to `height`";
    if (!a || a->empty() || a->size() > kMostPlanVertices) r.fail("heights", allowed);
    for (const toml::node& item : *a) {
      const auto h = finite_number(&item);
      if (!h || *h < 1 || *h > 1e7) r.fail("heights", allowed);
      b.heights.push_back(*h);
    }
  }
  b.storey = read_mm(r, "storey", 0, 0);
  if (b.storey > 0 && b.storey < 1000)
    r.fail("storey",
           "must be a storey's floor-to-floor height, at least 1000 mm (or 0: one "
           "storey the wall's height)");
  read_storeys(r, b);
  if (const toml::node* n = r.get("base")) {
    const auto base = finite_number(n);
    if (!base || std::fabs(*base) > 1e7)
      r.fail("base", "must be the wall's base level in millimetres, within 10 km");
    b.base = *base;
  }
  b.depth = read_mm(r, "depth", 0, 0);
  const size_t corners = plan ? b.plan.size() : 0;
  b.start = static_cast<size_t>(
      read_int(r, "start", 0, 0, corners ? static_cast<int64_t>(corners) - 1 : 0));
  if (r.get("phase")) {
    if (!plan) r.fail("phase", "turns the field round a building (plan); a path has two ends");
    b.phase = read_int(r, "phase", 0, 0, int64_t{1} << 30);
  }
  b.coursed_openings = read_bool(r, "coursed_openings", true);
  b.bent_on_arcs = bent_by_default;
  if (const auto arcs = read_string(r, "arcs", "how units lie on an arc")) {
    if (*arcs != "chords" && *arcs != "bent")
      r.fail("arcs",
             "must be \"chords\" (straight units on chords of the arc: bricks, blocks) or "
             "\"bent\" (units bent to the arc: cladding panels, ordered by their developed size)");
    b.bent_on_arcs = *arcs == "bent";
  }
  read_wall(r, b);
  if (const toml::node* n = r.get("openings")) {
    const toml::array* a = n->as_array();
    if (!a || a->size() > kMostOpenings)
      r.fail("openings", "must be [[layout.building.openings]] tables, at most 10000");
    for (size_t i = 0; i < a->size(); ++i) {
      const toml::table* o = a->get(i)->as_table();
      const std::string where = r.key_path("openings") + "." + std::to_string(i);
      if (!o) r.fail_node(*a->get(i), where, "must be a table: facade, rect, type");
      TableReader ro(*o, where, r.source(), {"facade", "rect", "type", "replaces"});
      b.openings.push_back(read_opening(ro, i));
    }
  }
  if (r.get("elevations")) {
    const std::vector<BuildingOpening> drawn_openings = read_site_elevations(r, spec);
    b.openings.insert(b.openings.end(), drawn_openings.begin(), drawn_openings.end());
  }
  if (r.get("windows")) {
    const toml::table* w = read_table(r, "windows");
    if (!w) r.fail("windows", "must be a table: size, every, clear, sill, omit");
    TableReader rw(*w, r.key_path("windows"), r.source(),
                   {"size", "every", "clear", "sill", "omit"});
    b.windows = read_windows(rw);
  }
  r.report_unused("is not a key of layout.building");
  try {
    // The plan, heights, openings and corners checked where they are read.
    Envelope envelope = envelope_of(b, spec);
    check_corner_room(envelope, spec);
    return {std::move(b), std::move(envelope)};
  } catch (const ResourceLimitError& e) {  // too big: where its height is, still a limit
    throw ResourceLimitError(locate(r.source(), r.get("height")->source(), r.key_path("height")),
                             e.message());
  } catch (const InputError& e) {
    r.fail(e.where().key, e.message());
  }
}

}  // namespace curdle::reading
