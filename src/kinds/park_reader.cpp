// [layout] of kind "park": what each curd places in its cells, the ground and the clearance
// (Cirovic 2014, fig. 5).
#include <algorithm>

#include "curdle/markov.h"
#include "kinds/park.h"
#include "recipe/layout_reader.h"

namespace curdle::reading {
namespace {

// Stem girth at 1 m, cm, as nurseries sell it: [from, to], or one number for both.
std::array<double, 2> read_girth(TableReader& r) {
  const toml::node* n = r.get("girth");
  if (!n) return {0, 0};
  const char* allowed =
      "must be the stem girth at 1 m in cm, 1 to 1000: a number, or [from, to] "
      "with from <= to, e.g. [18, 20]";
  std::vector<const toml::node*> parts;
  if (const toml::array* a = n->as_array())
    for (size_t i = 0; i < a->size(); ++i) parts.push_back(a->get(i));
  else
    parts = {n, n};
  if (parts.size() != 2) r.fail("girth", allowed);
  std::array<double, 2> g{};
  for (size_t i = 0; i < 2; ++i) {
    const std::optional<double> v = finite_number(parts[i]);
    if (!v || *v < 1 || *v > 1000) r.fail("girth", allowed);
    g[i] = *v;
  }
  if (g[0] > g[1]) r.fail("girth", allowed);
  return g;
}

// What the contractor orders for an object: its species (or product), girth, root ball and pit.
PlantingSpec read_planting(TableReader& r) {
  PlantingSpec p;
  p.species = read_name(r, "species",
                        "a botanical or product name, e.g. \"Tilia cordata "
                        "'Greenspire'\"")
                  .value_or("");
  p.girth = read_girth(r);
  p.root_ball = read_mm(r, "root_ball", 0, 1);
  if (const auto pit = read_mm_pair(r, "pit")) {
    p.pit = *pit;
    if (p.root_ball > 0 && (p.pit[0] < p.root_ball || p.pit[1] < p.root_ball))
      r.fail("pit", "must take the root ball: each side at least its " +
                        std::to_string(static_cast<int>(p.root_ball)) + " mm");
  }
  return p;
}

ParkElement read_park_element(TableReader& r, bool ground) {
  ParkElement e;
  e.type = read_name(r, "type", "a name such as \"tree\"").value_or(ground ? "white paving" : "");
  if (e.type.empty())
    r.fail("type", "is required: what the curd places, e.g. \"tree\", \"bench\", \"grey paving\"");
  const std::string form =
      ground ? "surface" : read_string(r, "form", "\"surface\" or \"object\"").value_or("object");
  if (form != "surface" && form != "object")
    r.fail("form",
           "must be \"surface\" (fills the cell, like paving) or \"object\" (stands in it)");
  e.surface = form == "surface";
  if (auto c = read_string(r, "colour", "a colour written \"#rrggbb\"")) {
    const auto colour = parse_colour(*c);
    if (!colour) r.fail("colour", "must be a colour written \"#rrggbb\"");
    e.colour = *colour;
  } else {
    e.colour = ground ? Rgb{242, 240, 234} : e.surface ? Rgb{140, 140, 140} : Rgb{58, 138, 79};
  }
  if (!e.surface) {
    const auto shape = read_string(r, "shape", "\"circle\" or \"rectangle\"").value_or("circle");
    if (shape != "circle" && shape != "rectangle")
      r.fail("shape", "must be \"circle\" or \"rectangle\"");
    e.round = shape == "circle";
    const auto size = read_mm_pair(r, "size", true);
    e.w = (*size)[0], e.h = e.round ? (*size)[0] : (*size)[1];
    e.order = read_planting(r);
    e.faces = read_name(r, "faces", "a surface's type or a zone's name").value_or("");
    if (!e.faces.empty() && e.round)
      r.fail("faces", "is for a rectangular object (a bench); a round one faces every way");
  }
  return e;
}

}  // namespace

void read_park(TableReader& r, const Design& design, LayoutSpec& spec) {
  spec.own<ParkKeys>().clearance = read_mm(r, "clearance", 0, 0);
  if (const toml::node* g = r.get("ground")) {
    if (!g->as_table())
      r.fail("ground", "must be a table {type = \"white paving\", colour = \"#f2f0ea\"}");
    TableReader gr(*g->as_table(), "layout.ground", r.source(), {"type", "colour"});
    spec.own<ParkKeys>().ground = read_park_element(gr, true);
  }
  const toml::node* n = r.get("elements");
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->size() != curd_members(design.curds).size())
    r.fail("elements", "must give one element per curd, and per state of a Markov curd (" +
                           std::to_string(curd_members(design.curds).size()) +
                           "), e.g. {type = \"tree\", form = \"object\", shape = \"circle\", size "
                           "= [2400, 2400]}");
  size_t objects = 0;
  for (size_t i = 0; i < a->size(); ++i) {
    const std::string path = "layout.elements." + std::to_string(i);
    if (!a->get(i)->as_table())
      r.fail_node(*a->get(i), path, "must be a table {type = ..., form = ...}");
    TableReader er(*a->get(i)->as_table(), path, r.source(),
                   {"type", "form", "shape", "size", "colour", "species", "girth", "root_ball",
                    "pit", "faces"});
    spec.own<ParkKeys>().elements.push_back(read_park_element(er, false));
    objects += !spec.own<ParkKeys>().elements.back().surface;
  }
  // Every object must fit in its slot when all the objects share one cell.
  const Rect cell{0, 0, spec.module_w, spec.module_h};
  const std::vector<Rect> slots = object_slots(cell, objects, spec.own<ParkKeys>().clearance);
  for (size_t i = 0; i < spec.own<ParkKeys>().elements.size(); ++i) {
    const ParkElement& e = spec.own<ParkKeys>().elements[i];
    if (e.surface || slots.empty()) continue;
    if (e.w > slots[0].w + 1e-9 || e.h > slots[0].h + 1e-9 || slots[0].w <= 0 || slots[0].h <= 0)
      r.fail_node(*a->get(i), "layout.elements." + std::to_string(i),
                  "a " + e.type + " of " + std::to_string(static_cast<int>(e.w)) + " x " +
                      std::to_string(static_cast<int>(e.h)) + " mm does not fit when " +
                      std::to_string(objects) + " objects share a " +
                      std::to_string(static_cast<int>(spec.module_w)) + " x " +
                      std::to_string(static_cast<int>(spec.module_h)) + " mm cell with " +
                      std::to_string(static_cast<int>(spec.own<ParkKeys>().clearance)) +
                      " mm clearance (each gets " +
                      std::to_string(static_cast<int>(std::max(0.0, slots[0].w))) + " x " +
                      std::to_string(static_cast<int>(std::max(0.0, slots[0].h))) +
                      " mm); use smaller elements, a larger cell or less clearance");
  }
}

void check_park_faces(TableReader& r, const LayoutSpec& spec) {
  const ParkKeys& park = spec.own<ParkKeys>();
  std::vector<std::string> known{park.ground.type};
  for (const ParkElement& e : park.elements)
    if (e.surface) known.push_back(e.type);
  for (const Zone& z : spec.zones) known.push_back(z.name);
  for (size_t i = 0; i < park.elements.size(); ++i) {
    const std::string& faces = park.elements[i].faces;
    if (faces.empty() || std::find(known.begin(), known.end(), faces) != known.end()) continue;
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "\"" : ", \"") + k + "\"";
    r.fail("elements", "element " + std::to_string(i) + " faces \"" + faces +
                           "\", which is no surface's type or zone's name here: " + list);
  }
}

}  // namespace curdle::reading
