#include "export/gltf/gltf.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <unordered_map>

#include "curdle/error.h"
#include "curdle/markov.h"
#include "curdle/palette.h"
#include "curdle/stop.h"
#include "export/gltf/gltf_json.h"
#include "export/gltf/gltf_model.h"
#include "export/gltf/gltf_screen.h"
#include "layout/framed_boxes.h"
#include "layout/framed_corner.h"
#include "layout/framed_sheet.h"
#include "layout/gltf_solids.h"
#include "layout/piece.h"
#include "layout/sheet_tiles.h"
#include "layout/standing_body.h"
#include "layout/triangulation.h"
#include "layout/union.h"

namespace curdle {
namespace {

std::string fmt_value_name(const LegendEntry& e) {
  return "value " + std::to_string(e.value) + " " + e.label;
}

// Appends an axis-aligned box (glTF metres, min corner and size) with outward normals.
void add_box(std::vector<Vec3>& pos, std::vector<Vec3>& nrm, std::vector<uint32_t>& idx, Vec3 lo,
             Vec3 size) {
  static const int faces[6][4][3] = {
      {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}, {{0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {0, 0, 0}},
      {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}, {{0, 0, 1}, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}},
      {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, {{1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}}};
  static const Vec3 normals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    const uint32_t base = static_cast<uint32_t>(pos.size());
    for (int v = 0; v < 4; ++v) {
      pos.push_back({lo[0] + size[0] * faces[f][v][0], lo[1] + size[1] * faces[f][v][1],
                     lo[2] + size[2] * faces[f][v][2]});
      nrm.push_back(normals[f]);
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) idx.push_back(base + i);
  }
}

// A box in layout millimetres: the rect in the plane, `base` to `base + t` out of it.
std::pair<Vec3, Vec3> box_of(const Layout& l, const Rect& r, double base, double t) {
  const Vec3 a = to_gltf(l, r.x, r.y, base), b = to_gltf(l, r.right(), r.top(), base + t);
  return {Vec3{std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2])},
          Vec3{std::fabs(b[0] - a[0]), std::fabs(b[1] - a[1]), std::fabs(b[2] - a[2])}};
}

// What a value holds: each plain curd by name, a Markov curd by its state's name.
tinygltf::Value::Array value_names(const Provenance& design, uint32_t value) {
  tinygltf::Value::Array names;
  const std::vector<CurdMember> members = curd_members(design.curds);
  for (const size_t m : members_of(design.curds, value))
    names.push_back(tinygltf::Value(members[m].name));
  return names;
}

tinygltf::Value element_extras(const Element& e, const Provenance& design,
                               const tinygltf::Value::Array& names) {
  tinygltf::Value::Object o;
  o["value"] = tinygltf::Value(static_cast<int>(e.value));
  tinygltf::Value::Array bits;
  for (size_t c = 0; c < design.curds.size(); ++c)
    bits.push_back(tinygltf::Value(static_cast<int>(e.value >> c & 1)));
  o["curd_bits"] = tinygltf::Value(bits);
  o["curds"] = tinygltf::Value(names);
  o["row"] = tinygltf::Value(static_cast<int>(e.row));
  o["column"] = tinygltf::Value(static_cast<int>(e.column));
  if (e.cut) o["cut"] = tinygltf::Value(true);
  if (!e.type.empty()) o["type"] = tinygltf::Value(e.type);
  return tinygltf::Value(o);
}

// A glTF scene of a layout under construction: the model, the value materials, and the
// unit boxes every box-shaped element shares.
struct Scene {
  const Layout& layout;
  const Provenance& design;
  ModelBuilder b;
  std::vector<int>& roots = b.model.scenes[0].nodes;
  double t;  // the thickness of what is laid, mm
  double metallic;
  std::vector<int> material;  // per value
  std::map<int, int> box_mesh;
  std::map<std::vector<int64_t>, int> prism_mesh;    // a corner unit's, by shape and material
  std::map<uint32_t, tinygltf::Value::Array> names;  // per value, worked out once

  explicit Scene(const Layout& l)
      : layout(l), design(l.source), t(l.thickness), metallic(l.kind->finish().metallic) {
    material.resize(layout.legend.size());
    for (const LegendEntry& e : layout.legend)
      material[e.value] =
          b.add_material(fmt_value_name(e), e.colour, metallic, l.kind->finish().roughness);
  }

  // Unit boxes, one mesh per material, placed by each node's translation and scale.
  int unit_box(int mat) {
    auto it = box_mesh.find(mat);
    if (it != box_mesh.end()) return it->second;
    std::vector<Vec3> p, n;
    std::vector<uint32_t> i;
    add_box(p, n, i, {-0.5f, -0.5f, -0.5f}, {1, 1, 1});
    return box_mesh[mat] =
               b.add_mesh("box " + b.model.materials[mat].name, {b.primitive(p, n, i, mat)});
  }
  // A node that carries a unit box to the rect, `base` to `base + height` out of the plane.
  tinygltf::Node placed(const Rect& r, double base, double height) const {
    const auto [lo, size] = box_of(layout, r, base, height);
    tinygltf::Node n;
    n.translation = {lo[0] + size[0] / 2.0, lo[1] + size[1] / 2.0, lo[2] + size[2] / 2.0};
    n.scale = {size[0], size[1], size[2]};
    return n;
  }
  // A node that carries a unit box to a box of a building (framed_boxes.h): turned about the
  // vertical to lie along its façade.
  tinygltf::Node framed_node(const FramedBox& f, int mat) {
    tinygltf::Node n;
    n.translation = {f.centre[0] / 1000, f.centre[2] / 1000, -f.centre[1] / 1000};
    const double turn = std::atan2(f.along[1], f.along[0]);
    n.rotation = {0, std::sin(turn / 2), 0, std::cos(turn / 2)};
    n.scale = {f.length / 1000, f.height / 1000, f.depth / 1000};
    n.mesh = unit_box(mat);
    return n;
  }
  // A node that lays a corner unit's prism (framed_corner.h): one mesh per shape, moved to its
  // footprint's first point and its course.
  tinygltf::Node prism_node(const FramedPrism& f, int mat) {
    const std::array<double, 2> o = f.footprint.front();
    Ring ring;
    std::vector<int64_t> key{mat, std::llround(f.height * 1e3)};
    for (const auto& v : f.footprint) {
      ring.push_back({v[0] - o[0], v[1] - o[1]});
      key.push_back(std::llround(ring.back()[0] * 1e3)),
          key.push_back(std::llround(ring.back()[1] * 1e3));
    }
    auto [it, added] = prism_mesh.try_emplace(key, 0);
    if (added) {
      std::vector<std::array<std::array<double, 2>, 3>> triangles;
      for (const auto& tri : footprint_triangles(f.footprint))
        triangles.push_back({ring[tri[0]], ring[tri[1]], ring[tri[2]]});
      std::vector<Vec3> p, n;
      std::vector<uint32_t> i;
      add_caps(false, triangles, 0, f.height, p, n, i);
      add_walls(false, {ring}, 0, f.height, p, n, i);
      it->second = b.add_mesh("corner " + b.model.materials[mat].name, {b.primitive(p, n, i, mat)});
    }
    tinygltf::Node node;
    node.translation = {o[0] / 1000, f.base / 1000, -o[1] / 1000};
    node.mesh = it->second;
    return node;
  }
  tinygltf::Node box_node(const Rect& r, double base, double height, int mat) {
    tinygltf::Node n = placed(r, base, height);
    n.mesh = unit_box(mat);
    return n;
  }
  // A root node named by the element's ID, carrying its value and curds.
  void add_named(const Element& e, tinygltf::Node n) {
    n.name = e.id;
    auto it = names.find(e.value);
    if (it == names.end()) it = names.emplace(e.value, value_names(design, e.value)).first;
    n.extras = element_extras(e, design, it->second);
    roots.push_back(b.add_node(std::move(n)));
  }
};

// The bed tiles and paving lie in, showing in the joints.
void add_bed(Scene& sc) {
  const Layout& layout = sc.layout;
  ModelBuilder& b = sc.b;
  std::vector<int>& roots = sc.roots;
  const double t = sc.t;
  const int bed =
      b.add_material("joint", layout.joint > 0 ? layout.joint_colour : Rgb{200, 200, 200}, 0, 1);
  // Under the surface only: not beyond an outline, nor under an excluded zone or opening.
  const Rect surface{0, 0, layout.width, layout.height};
  if (layout.cut_away.empty()) {
    const std::vector<Rect> beds = subtract(surface, layout.holes());
    for (size_t i = 0; i < beds.size(); ++i) {
      tinygltf::Node n = sc.box_node(beds[i], -5, t * 0.8 + 5, bed);
      n.name = i ? "bed-" + std::to_string(i) : "bed";
      roots.push_back(b.add_node(std::move(n)));
    }
  } else {  // sloping or curved edges: one solid along them
    std::vector<Vec3> p, n;
    std::vector<uint32_t> idx;
    for (const Outline& o : surfaced(surface, layout.holes(), layout.cut_away))
      add_prism(layout, o.rings, -5, t * 0.8, p, n, idx);
    tinygltf::Node node;
    node.name = "bed";
    node.mesh = b.add_mesh("bed", {b.primitive(p, n, idx, bed)});
    roots.push_back(b.add_node(std::move(node)));
  }
}

// A perforated sheet: one solid with its openings as holes, drawn as the sheet less the
// squares of its tiled openings and a shared tile per diameter or merged shape in each
// (sheet_tiles.h), and a named node per opening.
void add_sheet(Scene& sc) {
  const Layout& layout = sc.layout;
  ModelBuilder& b = sc.b;
  const double t = sc.t;
  std::vector<Ring> rings;  // the surface (the rectangle, or its outline)
  for (const Outline& o :
       surfaced(Rect{0, 0, layout.width, layout.height}, layout.outside, layout.cut_away))
    rings.insert(rings.end(), o.rings.begin(), o.rings.end());
  const SheetTiles tiles = sheet_tiles(layout, rings);
  rings.insert(rings.end(), tiles.holes.begin(), tiles.holes.end());
  std::vector<Ring> cut = rings;
  cut.insert(cut.end(), tiles.squares.begin(), tiles.squares.end());
  std::vector<Vec3> p, n;
  std::vector<uint32_t> idx;
  add_caps(layout.kind->upright(), triangulate(cut), 0, t, p, n, idx);
  add_walls(layout.kind->upright(), rings, 0, t, p, n, idx);
  const int metal = b.add_material("aluminium sheet", Rgb{201, 205, 210}, 0.9, 0.4);
  tinygltf::Node node;
  node.name = "sheet";
  node.mesh = b.add_mesh("sheet", {b.primitive(p, n, idx, metal)});
  auto tile_mesh = [&](const OpeningTile& tile, const std::string& name) {
    std::vector<Vec3> tp, tn;
    std::vector<uint32_t> ti;
    add_tile_solid(layout.kind->upright(), tile, t, tp, tn, ti);
    return b.add_mesh(name, {b.primitive(tp, tn, ti, metal)});
  };
  std::map<double, int> round_tiles;  // by diameter
  // Merged openings by their ring from the box's corner, to a nanometre: one shape, one mesh.
  std::map<std::vector<std::array<double, 2>>, int> merged_tiles;
  for (const size_t i : tiles.tiled) {
    stop_point();
    const Element& e = layout.elements[i];
    int mesh = -1;
    std::array<double, 2> corner{};
    if (e.outline) {
      const Ring& ring = e.outline->rings[0];
      const std::array<double, 4> box = outline_box(ring);
      corner = {box[0], box[1]};
      std::vector<std::array<double, 2>> shape;
      for (const auto& [x, y] : ring)
        shape.push_back({std::round((x - corner[0]) * 1e6), std::round((y - corner[1]) * 1e6)});
      auto it = merged_tiles.find(shape);
      if (it == merged_tiles.end())
        it = merged_tiles
                 .emplace(std::move(shape),
                          tile_mesh(outline_tile(ring), fmt::format("sheet round merged opening {}",
                                                                    merged_tiles.size() + 1)))
                 .first;
      mesh = it->second;
    } else {
      const Circle& c = *e.circle;
      corner = {c.cx, c.cy};
      auto it = round_tiles.find(c.d);
      if (it == round_tiles.end())
        it = round_tiles
                 .emplace(c.d, tile_mesh(opening_tile(c.d, layout.chord_tolerance),
                                         fmt::format("sheet round a {:g} mm opening", c.d)))
                 .first;
      mesh = it->second;
    }
    tinygltf::Node part;
    part.mesh = mesh;
    const Vec3 at = to_gltf(layout, corner[0], corner[1], 0);
    part.translation = {at[0], at[1], at[2]};
    node.children.push_back(b.add_node(std::move(part)));
  }
  sc.roots.push_back(b.add_node(std::move(node)));
  for (const Element& e : layout.elements) {  // each opening, named, at its centre
    stop_point();
    tinygltf::Node h;
    const Rect r = laid_bounds(e);
    const Vec3 c = to_gltf(layout, r.x + r.w / 2, r.y + r.h / 2, t / 2);
    h.translation = {c[0], c[1], c[2]};
    sc.add_named(e, std::move(h));
  }
}

// A perforated screen on a building: each fabrication sheet a solid laid on its façade's frame
// (rolled to an arc), its tiles placed on the face round their openings, and a named node per
// opening at the middle of its face, where schedule.csv places it.
void add_framed_screen(Scene& sc) {
  const Layout& layout = sc.layout;
  const int metal = sc.b.add_material("aluminium sheet", Rgb{201, 205, 210}, 0.9, 0.4);
  const std::vector<int> sheets = add_screen_sheets(sc.b, layout, metal);
  sc.roots.insert(sc.roots.end(), sheets.begin(), sheets.end());
  for (const Element& e : layout.elements) {  // each opening, named, at its face's middle
    stop_point();
    const BuildingPoint c = framed_centre(layout, e);
    tinygltf::Node h;
    h.translation = {c[0] / 1000, c[2] / 1000, -c[1] / 1000};
    sc.add_named(e, std::move(h));
  }
}

// Blocks: a node per block, its box showing only the faces that are not against another.
void add_blocks(Scene& sc) {
  const Layout& layout = sc.layout;
  ModelBuilder& b = sc.b;
  const std::vector<int>& material = sc.material;
  // A node per block, named by its ID: a unit box in its value's material with only the
  // faces that show (a face between two blocks is inside), shared by the blocks whose
  // value and shown faces agree.
  std::set<std::array<int64_t, 3>> solid;
  for (const Element& e : layout.elements) solid.insert({e.cell_x, e.cell_y, e.cell_z});
  // add_box's faces are +X, -X, +Y (up), -Y, +Z, -Z in glTF; as lattice steps (glTF +Z is
  // lattice -y):
  static const int step[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 0, 1},
                                 {0, 0, -1}, {0, -1, 0}, {0, 1, 0}};
  std::map<std::pair<uint32_t, int>, int> block_mesh;
  auto mesh_for = [&](uint32_t value, int shown) {
    auto it = block_mesh.find({value, shown});
    if (it != block_mesh.end()) return it->second;
    std::vector<Vec3> bp, bn, p, n;
    std::vector<uint32_t> bi, idx;
    add_box(bp, bn, bi, {-0.5f, -0.5f, -0.5f}, {1, 1, 1});
    for (int f = 0; f < 6; ++f) {
      if (!(shown >> f & 1)) continue;
      const uint32_t base = static_cast<uint32_t>(p.size());
      for (int v = 0; v < 4; ++v) p.push_back(bp[f * 4 + v]), n.push_back(bn[f * 4 + v]);
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) idx.push_back(base + i);
    }
    return block_mesh[{value, shown}] =
               b.add_mesh("block " + b.model.materials[material[value]].name + " faces " +
                              std::to_string(shown),
                          {b.primitive(p, n, idx, material[value])});
  };
  const double w = layout.module_w, d = layout.module_h, h = layout.level_height;
  for (const Element& e : layout.elements) {
    stop_point();
    const Rect plan{(e.cell_x - layout.view.origin[0]) * w, (e.cell_y - layout.view.origin[1]) * d,
                    w, d};
    tinygltf::Node node = sc.placed(plan, (e.cell_z - layout.view.origin[2]) * h, h);
    int shown = 0;
    for (int f = 0; f < 6; ++f)
      if (!solid.count({e.cell_x + step[f][0], e.cell_y + step[f][1], e.cell_z + step[f][2]}))
        shown |= 1 << f;
    node.mesh = shown ? mesh_for(e.value, shown) : -1;  // a block wholly inside shows nothing
    sc.add_named(e, std::move(node));
  }
}

// Park elements: a mesh per element type (a tree's trunk and canopy), shared.
void add_park(Scene& sc) {
  const Layout& layout = sc.layout;
  ModelBuilder& b = sc.b;
  const double t = sc.t;
  // One mesh per element type, shared by every element of the type.
  std::map<std::string, int> type_mesh;
  for (const Element& e : layout.elements) {
    stop_point();
    if (type_mesh.count(e.type)) continue;
    const int mat = b.add_material(e.type, e.colour, 0, 0.9);
    std::vector<Vec3> p, n;
    std::vector<uint32_t> i;
    if (e.circle) {  // a tree: trunk and canopy, the canopy's diameter that of the element
      const float r = static_cast<float>(e.circle->d / 2000);
      const auto across = static_cast<float>(kTrunkWidth / 1000),
                 tall = static_cast<float>(kTrunkHeight / 1000);
      add_box(p, n, i, {-across / 2, 0, -across / 2}, {across, tall, across});
      const int trunk = b.add_material(e.type + " trunk", Rgb{92, 64, 44}, 0, 0.9);
      std::vector<Vec3> cp, cn;
      std::vector<uint32_t> ci;
      const int rings = 8, segments = 12;
      for (int a = 0; a <= rings; ++a)
        for (int s2 = 0; s2 <= segments; ++s2) {
          const double th = 3.14159265358979 * a / rings, ph = 2 * 3.14159265358979 * s2 / segments;
          const Vec3 dir{float(std::sin(th) * std::cos(ph)), float(std::cos(th)),
                         float(std::sin(th) * std::sin(ph))};
          cp.push_back({dir[0] * r, tall + r + dir[1] * r, dir[2] * r});
          cn.push_back(dir);
        }
      for (int a = 0; a < rings; ++a)
        for (int s2 = 0; s2 < segments; ++s2) {
          const uint32_t q = a * (segments + 1) + s2, q2 = q + segments + 1;
          ci.insert(ci.end(), {q, q + 1, q2, q + 1, q2 + 1, q2});
        }
      type_mesh[e.type] =
          b.add_mesh(e.type, {b.primitive(p, n, i, trunk), b.primitive(cp, cn, ci, mat)});
    } else {
      type_mesh[e.type] = sc.unit_box(mat);
    }
  }
  for (const Element& e : layout.elements) {
    stop_point();
    tinygltf::Node n;
    if (e.circle) {
      const Vec3 c = to_gltf(layout, e.circle->cx, e.circle->cy, t);
      n.mesh = type_mesh[e.type];
      n.translation = {c[0], c[1], c[2]};
    } else if (e.outline) {  // a surface cut along a sloping or curved edge
      std::vector<Vec3> p, nr;
      std::vector<uint32_t> idx;
      add_prism(layout, e.outline->rings, 0, t, p, nr, idx);
      n.mesh = b.add_mesh(
          "piece " + e.id,
          {b.primitive(p, nr, idx, b.model.meshes[type_mesh[e.type]].primitives[0].material)});
    } else {
      const int mat = b.model.meshes[type_mesh[e.type]].primitives[0].material;
      const bool surface = !e.stands;
      if (e.shape.size() == 1) {
        n = sc.box_node(e.shape[0], surface ? 0 : t, surface ? t : kStandingHeight, mat);
      } else {  // a surface cut to several rectangles by an outline along x and y
        for (const Rect& r : e.shape) n.children.push_back(b.add_node(sc.box_node(r, 0, t, mat)));
      }
    }
    sc.add_named(e, std::move(n));
  }
}

// Pieces: tiles, paving, panels, fins.
void add_pieces(Scene& sc) {
  const Layout& layout = sc.layout;
  const Provenance& design = sc.design;
  ModelBuilder& b = sc.b;
  const std::vector<int>& material = sc.material;
  const double t = sc.t, metallic = sc.metallic;
  // Tiles, paving, panels, fins: a node per element, named by its ID, sharing one unit box
  // per material, so that any importer keeps every element's identity at any size. In keep
  // mode each curd's stripe is a child in the curd's own colour, as the drawings show it.
  std::map<std::array<uint8_t, 3>, int> part_material;
  auto material_of = [&](const Element& e, const Rgb& colour) {
    if (colour == layout.legend[e.value].colour) return material[e.value];
    const std::array<uint8_t, 3> key{colour.r, colour.g, colour.b};
    auto it = part_material.find(key);
    if (it != part_material.end()) return it->second;
    std::string name = "part " + hex_colour(colour);
    for (size_t c = 0; c < design.curds.size(); ++c)
      if (curd_colour(design.curds, c) == colour) name = "curd " + design.curds[c].name;
    return part_material[key] = b.add_material(name, colour, metallic, 0.8);
  };
  for (const Element& e : layout.elements) {
    stop_point();
    if (e.outline) {  // cut along a sloping or curved edge: its own solid
      std::vector<Vec3> p, n;
      std::vector<uint32_t> idx;
      add_prism(layout, e.outline->rings, 0, t, p, n, idx);
      tinygltf::Node node;
      node.mesh = b.add_mesh("piece " + e.id, {b.primitive(p, n, idx, material[e.value])});
      sc.add_named(e, std::move(node));
      continue;
    }
    const std::vector<ColouredRect> parts = keep_stripes(layout, e);
    if (parts.size() == 1) {
      sc.add_named(e, sc.box_node(parts[0].rect, 0, t, material_of(e, parts[0].colour)));
      continue;
    }
    tinygltf::Node parent;  // a cut element in pieces, or a kept element in stripes
    for (const ColouredRect& part : parts)
      parent.children.push_back(
          b.add_node(sc.box_node(part.rect, 0, t, material_of(e, part.colour))));
    sc.add_named(e, std::move(parent));
  }
}

// A building's units, each placed through the frames of its façades (a unit that turns a
// corner whole as one prism, cut to the corner's angle), and the mortar behind them, set back
// from the face.
void add_framed_pieces(Scene& sc) {
  const Layout& layout = sc.layout;
  const double t = sc.t;
  const int mortar = sc.b.add_material("mortar", layout.joint_colour, 0, 1);
  const double kSetBack = 8;  // a recessed joint, mm
  // A one-brick wall's backing leaf behind the face leaf and its collar joint, in a common
  // brick's colour: the headers run into it, as they are bonded into it.
  const WallBacking* backed = layout.backing();
  const int backing =
      backed ? sc.b.add_material("backing: " + backed->material, kBackingColour, 0, 1) : mortar;
  const double mortar_to = backed ? backed->from : t;
  int part = 0;
  // Mortar shows in joints; fins standing off a wall have none.
  const bool jointed = !layout.kind->stands_off();
  for (const Rect& r : jointed ? subtract(Rect{0, 0, layout.width, layout.height}, layout.holes())
                               : std::vector<Rect>{}) {
    for (const FramedBox& f : framed_backing(layout, r, kSetBack, mortar_to, 600)) {
      tinygltf::Node n = sc.framed_node(f, mortar);
      n.name = "mortar-" + std::to_string(part++);
      sc.roots.push_back(sc.b.add_node(std::move(n)));
    }
    if (!backed) continue;
    for (const FramedBox& f : framed_backing(layout, r, backed->from, t, 600)) {
      tinygltf::Node n = sc.framed_node(f, backing);
      n.name = "backing-" + std::to_string(part++);
      sc.roots.push_back(sc.b.add_node(std::move(n)));
    }
  }
  for (const Element& e : layout.elements) {
    stop_point();
    const int mat = sc.material[e.value];
    if (const auto corner = framed_corner(layout, e, t)) {
      sc.add_named(e, sc.prism_node(*corner, mat));
      continue;
    }
    std::vector<FramedBox> boxes;
    const std::array<double, 2> depth = framed_depth(layout, e);  // a header runs in further
    for (const Rect& r : e.shape) {
      const std::vector<FramedBox> more = framed_boxes(layout, r, depth[0], depth[1]);
      boxes.insert(boxes.end(), more.begin(), more.end());
    }
    if (boxes.size() == 1) {
      sc.add_named(e, sc.framed_node(boxes[0], mat));
      continue;
    }
    tinygltf::Node parent;  // a unit that turns a corner, or cut at an opening
    for (const FramedBox& f : boxes)
      parent.children.push_back(sc.b.add_node(sc.framed_node(f, mat)));
    sc.add_named(e, std::move(parent));
  }
}

// The scene's extras: how to reproduce it.
void add_provenance(Scene& sc) {
  const Provenance& design = sc.design;
  ModelBuilder& b = sc.b;
  tinygltf::Value::Object scene;
  scene["recipe"] = tinygltf::Value(design.recipe);
  scene["seed"] = tinygltf::Value(std::to_string(design.seed));
  tinygltf::Value::Object lattice;
  lattice["base"] = tinygltf::Value(design.lattice.base);
  lattice["dimension"] = tinygltf::Value(design.lattice.dimension);
  lattice["stages"] = tinygltf::Value(design.lattice.stages);
  lattice["mode"] = tinygltf::Value(std::string(to_string(design.lattice.mode)));
  scene["lattice"] = tinygltf::Value(lattice);
  scene["units"] = tinygltf::Value(std::string("metres, +Y up"));
  // A whole building (layout frames): x east, -z north; viewers frame it from above a corner.
  if (sc.layout.envelope) scene["building"] = tinygltf::Value(true);
  b.model.scenes[0].name = design.recipe;
  b.model.scenes[0].extras = tinygltf::Value(scene);
}

struct Built {
  tinygltf::Model model;
  NodeText nodes;
};

Built build(const Layout& layout) {
  Scene sc(layout);
  if (layout.kind->bedded()) add_bed(sc);
  if (layout.envelope && layout.kind->ground() == Ground::sheet) {
    add_framed_screen(sc);
  } else if (layout.envelope) {
    add_framed_pieces(sc);
  } else if (layout.kind->ground() == Ground::sheet) {
    add_sheet(sc);
  } else {
    switch (layout.kind->depiction()) {
      case Depiction::views:
        add_blocks(sc);
        break;
      case Depiction::objects:
        add_park(sc);
        break;
      case Depiction::grid:
      case Depiction::shapes:
        add_pieces(sc);
        break;
    }
  }
  add_provenance(sc);
  return {std::move(sc.b.model), std::move(sc.b.nodes)};
}

}  // namespace

void write_glb(std::ostream& out, const Layout& layout) {
  const Built built = build(layout);
  write_glb_container(out, built.model, &built.nodes);
}

void write_gltf(std::ostream& json, std::ostream& bin, const std::string& bin_name,
                const Layout& layout) {
  const Built built = build(layout);
  const auto& data = built.model.buffers[0].data;
  bin.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
  write_gltf_json(json, built.model, bin_name, built.nodes);
  json << "\n";
}

}  // namespace curdle
