// glTF export read back with tinygltf: what the file holds matches the layout, names and all.
#include "export/gltf/gltf.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "app/run.h"
#include "curdle/curdling.h"
#include "export/drawing/svg.h"
#include "layout/builder.h"
#include "test_support.h"

namespace curdle {
namespace {

tinygltf::Model read_back(const Layout& layout) {
  std::ostringstream out;
  write_glb(out, layout);
  const std::string bytes = out.str();
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn,
                                          reinterpret_cast<const unsigned char*>(bytes.data()),
                                          static_cast<unsigned>(bytes.size())))
      << err;
  EXPECT_TRUE(warn.empty()) << warn;
  return model;
}

struct Totals {
  uint64_t triangles = 0;
  std::array<double, 3> lo{1e30, 1e30, 1e30}, hi{-1e30, -1e30, -1e30};
  std::set<std::string> names;
};

// Walks the scene applying each node's translation and scale (the exporter uses no rotation).
void walk(const tinygltf::Model& m, int index, std::array<double, 3> offset,
          std::array<double, 3> scale, Totals& t) {
  const tinygltf::Node& n = m.nodes[index];
  if (!n.name.empty()) t.names.insert(n.name);
  std::array<double, 3> o = offset, s = scale;
  for (int i = 0; i < 3; ++i) {
    if (n.translation.size() == 3) o[i] += s[i] * n.translation[i];
    if (n.scale.size() == 3) s[i] *= n.scale[i];
  }
  if (n.mesh >= 0)
    for (const auto& p : m.meshes[n.mesh].primitives) {
      t.triangles += m.accessors[p.indices].count / 3;
      const auto& pos = m.accessors[p.attributes.at("POSITION")];
      for (int i = 0; i < 3; ++i) {
        const double a = o[i] + s[i] * pos.minValues[i], b = o[i] + s[i] * pos.maxValues[i];
        t.lo[i] = std::min({t.lo[i], a, b});
        t.hi[i] = std::max({t.hi[i], a, b});
      }
    }
  for (int c : n.children) walk(m, c, o, s, t);
}

Totals totals(const tinygltf::Model& m) {
  Totals t;
  for (int root : m.scenes[0].nodes) walk(m, root, {0, 0, 0}, {1, 1, 1}, t);
  return t;
}

}  // namespace

TEST(Gltf, PavingReadsBackWithItsElementsMaterialsAndExtent) {
  Design d = test::design(4, 2, {{"3/4", "2/3", "1/2"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.module_w = spec.module_h = 300, spec.joint = 5;
  spec.size = std::array<double, 2>{6000, 4500};
  const auto cells = elements_to_cover(spec);
  d.field.size = {cells[0], cells[1], 1};
  const Layout layout = make_layout(d, curdle(d, 2, d.field), d.field, spec);
  const tinygltf::Model m = read_back(layout);
  const Totals t = totals(m);
  std::set<std::string> ids;
  for (const Element& e : layout.elements) ids.insert(e.id);
  std::set<std::string> element_names;
  for (const auto& n : t.names)
    if (ids.count(n)) element_names.insert(n);
  EXPECT_EQ(element_names, ids);                              // every element is a named node
  EXPECT_EQ(t.triangles, (layout.elements.size() + 1) * 12);  // boxes, and the bed
  EXPECT_EQ(m.materials.size(), layout.legend.size() + 1);    // a value each, and the joints
  EXPECT_NEAR(t.lo[0], 0, 1e-6);                              // metres, the floor on XZ
  EXPECT_NEAR(t.hi[0], 6.0, 1e-6);
  EXPECT_NEAR(t.lo[2], -4.5, 1e-6);
  EXPECT_NEAR(t.hi[2], 0, 1e-6);
  EXPECT_NEAR(t.hi[1], 0.030, 1e-6);  // 30 mm tiles, +Y up
  const auto& extras = m.scenes[0].extras;
  EXPECT_EQ(extras.Get("recipe").Get<std::string>(), "test");
  EXPECT_EQ(extras.Get("lattice").Get("base").Get<int>(), 4);
  // The same IDs name the SVG's elements: cut ones by id, the rest in merged ranges.
  std::ostringstream svg;
  write_layout_svg(svg, layout);
  const std::string text = svg.str();
  std::set<std::string> svg_ids;
  const std::regex named("(id|data-elements)=\"(P-R[0-9]+-C[0-9]+)(:P-R([0-9]+)-C([0-9]+))?\"");
  for (std::sregex_iterator it(text.begin(), text.end(), named), end; it != end; ++it) {
    const std::string first = (*it)[2];
    if (!(*it)[3].matched) {
      svg_ids.insert(first);
      continue;
    }
    const int r0 = std::stoi(first.substr(3, first.find("-C") - 3)),
              c0 = std::stoi(first.substr(first.find("-C") + 2));
    const int r1 = std::stoi((*it)[4]), c1 = std::stoi((*it)[5]);
    for (const Element& e : layout.elements)
      if (e.row >= r0 && e.row <= r1 && e.column >= c0 && e.column <= c1) svg_ids.insert(e.id);
  }
  EXPECT_EQ(svg_ids, ids);
}

TEST(Gltf, FacadeStandsUpWithItsOpeningsLeftOpen) {
  Design d = test::design(4, 2, {{"3/4", "2/3"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("facade"));
  spec.module_w = 600, spec.module_h = 300, spec.joint = 10;
  spec.size = std::array<double, 2>{6000, 3000};
  spec.own<FacadeKeys>().openings = {{1000, 0, 1200, 2100}};
  const auto cells = elements_to_cover(spec);
  d.field.size = {cells[0], cells[1], 1};
  const Layout layout = make_layout(d, curdle(d, 2, d.field), d.field, spec);
  const Totals t = totals(read_back(layout));
  uint64_t pieces = 0;
  for (const Element& e : layout.elements) pieces += e.shape.size();
  EXPECT_EQ(t.triangles, pieces * 12);
  EXPECT_NEAR(t.hi[1], 3.0, 1e-6);  // the wall's height along +Y
  EXPECT_NEAR(t.hi[2], 0.020, 1e-6);
}

TEST(Gltf, PerforatedSheetIsASolidWithItsOpenings) {
  Design d = test::design(4, 2, {{"1/2", "1/2"}, {"1/2", "1/2"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("perforation"));
  spec.combine = Combine::keep;
  spec.module_w = spec.module_h = 40;
  spec.size = std::array<double, 2>{640, 640};
  spec.own<PerforationKeys>().thickness = 3;
  spec.own<PerforationKeys>().holes = {{16, -6, 0}, {16, 6, 0}};
  spec.own<PerforationKeys>().chord_tolerance = 0.1;
  const Layout layout = make_layout(d, curdle(d, 3, d.field), d.field, spec);
  const tinygltf::Model m = read_back(layout);
  const Totals t = totals(m);
  // A screen stands: its sheet's y up (+Y), its thickness out of its face (+Z).
  EXPECT_NEAR(t.hi[0], 0.64, 1e-6);
  EXPECT_NEAR(t.hi[1], 0.64, 1e-6);
  EXPECT_NEAR(t.lo[2], 0, 1e-6);
  EXPECT_NEAR(t.hi[2], 0.003, 1e-6);
  size_t openings = 0;
  for (const Element& e : layout.elements) openings += t.names.count(e.id);
  EXPECT_EQ(openings, layout.elements.size());
  // The front face's area is the sheet less its openings: sum the triangles facing +Z over the
  // sheet's own mesh and the tiles it places round its round openings (sheet_tiles.h).
  const tinygltf::Node* sheet = nullptr;
  for (const tinygltf::Node& node : m.nodes)
    if (node.name == "sheet") sheet = &node;
  ASSERT_NE(sheet, nullptr);
  std::vector<int> meshes{sheet->mesh};
  for (int c : sheet->children) meshes.push_back(m.nodes[c].mesh);
  EXPECT_GT(sheet->children.size(), layout.elements.size() / 2) << "most openings are tiles";
  double top = 0;
  for (const int mesh : meshes) {
    const auto& prim = m.meshes[mesh].primitives[0];
    const auto& pos = m.accessors[prim.attributes.at("POSITION")];
    const auto& view = m.bufferViews[pos.bufferView];
    const float* p = reinterpret_cast<const float*>(m.buffers[0].data.data() + view.byteOffset);
    const auto& ia = m.accessors[prim.indices];
    const auto& iv = m.bufferViews[ia.bufferView];
    const uint32_t* idx =
        reinterpret_cast<const uint32_t*>(m.buffers[0].data.data() + iv.byteOffset);
    for (size_t i = 0; i < ia.count; i += 3) {
      const float* a = p + 3 * idx[i];
      const float* b = p + 3 * idx[i + 1];
      const float* c = p + 3 * idx[i + 2];
      if (a[2] < 0.0029 || b[2] < 0.0029 || c[2] < 0.0029) continue;
      top += 0.5 * std::fabs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
    }
  }
  // Polygons inscribed in the circles make openings a little smaller: the sheet keeps more
  // material than the exact circles leave, by at most perimeter x chord tolerance.
  double open = 0, slack = 0;
  for (const Element& e : layout.elements) {
    open += e.area();
    slack +=
        3.14159265358979 * 16 * spec.own<PerforationKeys>().chord_tolerance * (e.circle ? 1 : 2);
  }
  EXPECT_GE(top * 1e6, 640.0 * 640.0 - open - 1e-3);
  EXPECT_LE(top * 1e6, 640.0 * 640.0 - open + slack);
}

TEST(Gltf, BlocksLeaveOutTheFacesBetweenNeighbours) {
  const Design d = test::design(2, 3, {{"7/8", "3/4", "3/4"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("blocks"));
  spec.module_w = spec.module_h = 6000, spec.own<BlocksKeys>().voxel_h = 3000;
  const CurdField f = curdle(d, 3, d.field);
  const Layout layout = make_layout(d, f, d.field, spec);
  std::set<std::array<int64_t, 3>> solid;
  for (const Element& e : layout.elements) solid.insert({e.cell_x, e.cell_y, e.cell_z});
  uint64_t exposed = 0;
  for (const auto& c : solid)
    for (const auto& dv :
         {std::array<int, 3>{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}})
      exposed += !solid.count({c[0] + dv[0], c[1] + dv[1], c[2] + dv[2]});
  const Totals t = totals(read_back(layout));
  EXPECT_EQ(t.triangles, exposed * 2);
  EXPECT_NEAR(t.hi[1], 24.0, 1e-6);  // eight storeys of 3 m
}

// Above 20,000 elements every element keeps its own named node, and the file needs no extension
// an importer might lack; in keep mode each element shows its curds' stripes in their colours.
TEST(Gltf, EveryElementKeepsItsNodeAtAnySizeAndKeptStripesTakeTheCurdsColours) {
  Design d = test::design(
      2, 2, {std::vector<std::string>(8, "9/10"), std::vector<std::string>(8, "9/10")});
  d.curds[0].colour = Rgb{200, 40, 40}, d.curds[1].colour = Rgb{40, 40, 200};
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("tile"));
  spec.combine = Combine::keep;
  spec.module_w = spec.module_h = 100;
  d.field.size = {144, 144, 1};  // 20,736 tiles
  const Layout layout = make_layout(d, curdle(d, 6, d.field), d.field, spec);
  ASSERT_GT(layout.elements.size(), 20000u);
  const tinygltf::Model m = read_back(layout);
  EXPECT_TRUE(m.extensionsRequired.empty());
  EXPECT_TRUE(m.extensionsUsed.empty());
  std::map<std::string, const tinygltf::Node*> by_name;
  for (const tinygltf::Node& n : m.nodes) by_name[n.name] = &n;
  auto colour_of = [&](int mesh) {
    const auto& f = m.materials[m.meshes[mesh].primitives[0].material].pbrMetallicRoughness;
    return std::array<double, 3>{f.baseColorFactor[0], f.baseColorFactor[1], f.baseColorFactor[2]};
  };
  size_t both = 0;
  for (const Element& e : layout.elements) {
    ASSERT_TRUE(by_name.count(e.id)) << e.id;
    const tinygltf::Node& n = *by_name[e.id];
    if (e.value != 3) continue;  // both curds
    ++both;
    // Two stripes, each half the tile, the first curd's on the side laying starts from.
    ASSERT_EQ(n.children.size(), 2u) << e.id;
    const tinygltf::Node& first = m.nodes[n.children[0]];
    const tinygltf::Node& second = m.nodes[n.children[1]];
    EXPECT_NEAR(first.scale[0], 0.05, 1e-6);
    EXPECT_LT(first.translation[0], second.translation[0]);
    const auto a = colour_of(first.mesh), b = colour_of(second.mesh);
    EXPECT_GT(a[0], a[2]);  // red, in linear light
    EXPECT_GT(b[2], b[0]);  // blue
  }
  EXPECT_GT(both, 0u);
}

// A park's ground lies flat at its thickness wherever the site cuts its cells (a row cut short
// by layout.area, cells cut along a sloping or curved edge), and what stands on it starts on top:
// no ledge of ground boxes at an object's height.
TEST(Gltf, ParkGroundIsFlatWhereverTheSiteCutsItsCells) {
  for (const auto& [recipe, area] :
       {std::pair<std::string, std::string>{"examples/briefs/cafe-park.toml", ""},
        {"patterns/paper/fig5a-park.toml", "layout.area=[46000, 44500]"}}) {
    app::RunRequest request;
    request.recipe_path = std::string(CURDLE_SOURCE_DIR) + "/" + recipe;
    request.recipe_text = app::read_recipe_file(request.recipe_path);
    if (!area.empty()) request.overrides.push_back(area);
    const app::Run run = app::resolve_run(request);
    const Layout layout =
        make_layout(run.recipe.design, app::run_engine(run, 0), run.view, *run.recipe.layout);
    const tinygltf::Model m = read_back(layout);
    std::map<std::string, int> node_of;
    for (size_t i = 0; i < m.nodes.size(); ++i) node_of[m.nodes[i].name] = static_cast<int>(i);
    const double top = layout.thickness / 1000;
    size_t ground = 0, cut = 0, standing = 0;
    for (const Element& e : layout.elements) {
      ASSERT_TRUE(node_of.count(e.id)) << recipe << ": " << e.id;
      Totals t;
      walk(m, node_of[e.id], {0, 0, 0}, {1, 1, 1}, t);
      if (e.stands) {
        ++standing;
        EXPECT_NEAR(t.lo[1], top, 1e-6) << recipe << ": " << e.id << " stands on the ground";
        continue;
      }
      ++ground, cut += e.outline || e.area() < e.nominal.area() - 1;
      EXPECT_NEAR(t.lo[1], 0, 1e-6) << recipe << ": " << e.id;
      EXPECT_NEAR(t.hi[1], top, 1e-6) << recipe << ": " << e.id << " is not flat ground";
    }
    EXPECT_GT(ground, 0u);
    EXPECT_GT(cut, 0u) << recipe << ": the site cuts some cells";
    EXPECT_GT(standing, 0u);
  }
}

}  // namespace curdle
