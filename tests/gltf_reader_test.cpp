// Tests of gltf_reader.h: a massing model's footprint read as a plan layer. An L-shaped block
// made of three boxes (as a modeller leaves it: faces split where the boxes meet) reads as the
// pavilion's six corners, named by its node, with its height in the notes; the recipe's
// [layout.building.site] lays it; a file that refers outside itself, is no glTF or places its
// nodes without bound is refused.
#include "site/gltf_reader.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <limits>
#include <set>
#include <sstream>

#include "kinds/facade.h"
#include "recipe/recipe.h"
#include "recipe_support.h"
#include "site/site.h"

namespace curdle::site {
namespace {

// A glb of boxes (plan mm: x0, y0, x1, y1) from level 0 to `height` mm, one mesh, one node.
std::string boxes_glb(const std::vector<std::array<double, 4>>& boxes, double height,
                      const std::string& name) {
  std::vector<float> p;
  std::vector<uint32_t> idx;
  for (const auto& b : boxes) {
    const uint32_t base = static_cast<uint32_t>(p.size() / 3);
    for (int k = 0; k < 8; ++k) {
      const double x = k & 1 ? b[2] : b[0], y = k & 2 ? b[3] : b[1], z = k & 4 ? height : 0;
      p.insert(p.end(), {float(x / 1000), float(z / 1000), float(-y / 1000)});
    }
    for (uint32_t t : {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
                       2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3})
      idx.push_back(base + t);
  }
  tinygltf::Model m;
  m.asset.version = "2.0";
  tinygltf::Buffer buffer;
  buffer.data.resize(p.size() * 4 + idx.size() * 4);
  std::memcpy(buffer.data.data(), p.data(), p.size() * 4);
  std::memcpy(buffer.data.data() + p.size() * 4, idx.data(), idx.size() * 4);
  m.buffers.push_back(buffer);
  tinygltf::BufferView vp, vi;
  vp.buffer = vi.buffer = 0;
  vp.byteLength = p.size() * 4;
  vi.byteOffset = p.size() * 4;
  vi.byteLength = idx.size() * 4;
  m.bufferViews = {vp, vi};
  tinygltf::Accessor ap, ai;
  ap.bufferView = 0, ap.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT, ap.count = p.size() / 3;
  ap.type = TINYGLTF_TYPE_VEC3;
  ai.bufferView = 1, ai.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  ai.count = idx.size(), ai.type = TINYGLTF_TYPE_SCALAR;
  m.accessors = {ap, ai};
  tinygltf::Primitive prim;
  prim.attributes["POSITION"] = 0;
  prim.indices = 1;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.primitives = {prim};
  m.meshes = {mesh};
  tinygltf::Node node;
  node.name = name;
  node.mesh = 0;
  m.nodes = {node};
  tinygltf::Scene scene;
  scene.nodes = {0};
  m.scenes = {scene};
  m.defaultScene = 0;
  std::ostringstream out;
  tinygltf::TinyGLTF().WriteGltfSceneToStream(&m, out, false, true);
  return out.str();
}

// The pavilion's L: 20 x 12 m with an 8 x 6 m bite, as three boxes.
const std::vector<std::array<double, 4>> kPavilion{
    {0, 0, 12000, 6000}, {12000, 0, 20000, 6000}, {0, 6000, 12000, 12000}};

TEST(GltfReader, AMassingModelsFootprintIsItsNodesOutline) {
  const Drawing d = read_gltf(boxes_glb(kPavilion, 7050, "Pavilion"), "massing.glb");
  ASSERT_EQ(d.shapes.size(), 1u);
  EXPECT_EQ(d.shapes[0].layer, "Pavilion");
  EXPECT_EQ(d.unit_name, "m");
  EXPECT_NEAR(d.shapes[0].height, 7.05, 1e-6);
  EXPECT_TRUE(d.shapes[0].closed);
  std::set<std::pair<long, long>> corners;
  for (const ContourVertex& v : d.shapes[0].path)
    corners.insert({std::lround(v.x * 1000), std::lround(v.y * 1000)});  // metres, as glTF
  EXPECT_EQ(corners,
            (std::set<std::pair<long, long>>{
                {0, 0}, {20000, 0}, {20000, 6000}, {12000, 6000}, {12000, 12000}, {0, 12000}}));
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_NE(d.notes[0].find("6 corners at level 0.000 m, 7.050 m high"), std::string::npos)
      << d.notes[0];
}

TEST(GltfReader, ABuildingsPlanAndHeightAreReadFromTheModel) {
  FilesInMemory files;
  files.files["massing.glb"] = boxes_glb(kPavilion, 7050, "Pavilion");
  const Recipe r = parse_recipe(with_layout(R"(kind = "facade"
panel = [215, 65]
joint = 10
[layout.building]
height = 7050
[layout.building.site]
file = "massing.glb"
plan = "Pavilion"
)"),
                                "r.toml", {}, &files);
  const Envelope& env = *r.layout->own<FacadeKeys>().envelope;
  ASSERT_EQ(env.facades.size(), 6u);
  EXPECT_NEAR(env.length, 64000, 1e-6);
  // Without a height, the model's.
  const Recipe own = parse_recipe(with_layout(R"(kind = "facade"
panel = [215, 65]
joint = 10
[layout.building]
[layout.building.site]
file = "massing.glb"
plan = "Pavilion"
)"),
                                  "r.toml", {}, &files);
  ASSERT_TRUE(own.layout->own<FacadeKeys>().envelope.has_value());
  EXPECT_NEAR(own.layout->own<FacadeKeys>().envelope->length, 64000, 1e-6);
}

TEST(GltfReader, AModelThatIsNotGltfOrReachesOutsideIsRefused) {
  EXPECT_THROW(read_gltf("not a model", "massing.gltf"), InputError);
  const std::string outside = R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "/etc/passwd",
    "byteLength": 12}], "scenes": [{"nodes": []}], "scene": 0})";
  try {
    read_gltf(outside, "massing.gltf");
    ADD_FAILURE() << "a buffer outside the file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("massing.gltf"), std::string::npos) << e.what();
  }
  // Each node placing the next twice, 40 deep: 2^40 places, refused at a bound.
  std::string nodes;
  for (int k = 0; k < 40; ++k)
    nodes += "{\"children\": [" + std::to_string(k + 1) + ", " + std::to_string(k + 1) + "]}, ";
  const std::string doubling = R"({"asset": {"version": "2.0"}, "nodes": [)" + nodes +
                               R"({}], "scenes": [{"nodes": [0]}], "scene": 0})";
  try {
    read_gltf(doubling, "deep.gltf");
    ADD_FAILURE() << "2^40 node places were walked";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("places nodes more than 100000 times"), std::string::npos)
        << e.what();
  }
  // Two boxes apart: two outlines on the node's layer, which the site reader refuses as a plan
  // with their sizes unless one is picked.
  const Drawing two =
      read_gltf(boxes_glb({{0, 0, 1000, 1000}, {5000, 0, 6000, 1000}}, 3000, "Two"), "two.glb");
  ASSERT_EQ(two.shapes.size(), 2u);
  EXPECT_EQ(two.shapes[1].handle, "Two loop 2");
  ASSERT_EQ(two.notes.size(), 1u);
  EXPECT_NE(two.notes[0].find("2 footprint outlines"), std::string::npos);
  LayerMap map;
  map.file = "two.glb";
  map.outline = "Two";
  try {
    site_from(two, map);
    ADD_FAILURE() << "one of two outlines was picked";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds 2 closed shapes side by side (node Two loop 1 (1 x "
                                         "1 at (0, 0)); node Two loop 2 (1 x 1 at (5, 0)))"),
              std::string::npos)
        << e.what();
  }
}

// As SketchUp, Rhino and Blender export a model: the meshes under a parent (a named empty,
// turned and moved); every named node is a layer with its subtree, at any depth.
TEST(GltfReader, NamedNodesAtAnyDepthAreLayers) {
  tinygltf::Model m;
  std::string err, warn;
  const std::string glb = boxes_glb(kPavilion, 7050, "Block A");
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromMemory(
      &m, &err, &warn, reinterpret_cast<const unsigned char*>(glb.data()),
      static_cast<unsigned>(glb.size())));
  // A ground slab beside it, and both under "Massing", moved 100 m east (glTF x).
  tinygltf::Node slab = m.nodes[0];
  slab.name = "Ground";
  slab.scale = {3, 0.01, 3};
  tinygltf::Node parent;
  parent.name = "Massing";
  parent.translation = {100, 0, 0};
  parent.children = {0, 1};
  m.nodes.push_back(slab);
  m.nodes.push_back(parent);
  m.scenes[0].nodes = {2};
  std::ostringstream out;
  tinygltf::TinyGLTF().WriteGltfSceneToStream(&m, out, false, true);
  const Drawing d = read_gltf(out.str(), "grouped.glb");
  std::set<std::string> layers;
  for (const Shape& s : d.shapes) layers.insert(s.layer);
  EXPECT_EQ(layers, (std::set<std::string>{"Massing", "Block A", "Ground"}));
  for (const Shape& s : d.shapes)
    if (s.layer == "Block A") {
      EXPECT_NEAR(contour_bounds(s.path).x, 100, 1e-6);
      EXPECT_NEAR(s.height, 7.05, 1e-6);
    }
}

TEST(GltfReader, ANanVertexIsNamedAsSuch) {
  std::string glb = boxes_glb(kPavilion, 7050, "Pavilion");
  // The first position's x, just after the JSON chunk and the binary chunk's header.
  const uint32_t json_length = *reinterpret_cast<const uint32_t*>(glb.data() + 12);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(glb.data() + 20 + json_length + 8, &nan, 4);
  try {
    read_gltf(glb, "nan.glb");
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node \"Pavilion\" has a vertex that is not a finite"),
              std::string::npos)
        << e.what();
  }
}

// tinygltf's JSON parser recurses a level at a time: 20,000 nested arrays overflowed the stack
// (12,000 were refused); the nesting is measured before the parser sees it.
TEST(GltfReader, DeeplyNestedJsonIsRefusedBeforeParsing) {
  const std::string deep = R"({"asset": {"version": "2.0"}, "extras": )" + std::string(20000, '[') +
                           std::string(20000, ']') + "}";
  try {
    read_gltf(deep, "deep.gltf");
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nests arrays or objects more than 64 deep"),
              std::string::npos)
        << e.what();
  }
  // Brackets inside strings are text, not nesting.
  const std::string quoted = R"({"asset": {"version": "2.0", "generator": ")" +
                             std::string(100, '[') +
                             R"("}, "scenes": [{"nodes": []}], "scene": 0})";
  EXPECT_NO_THROW(read_gltf(quoted, "quoted.gltf"));
}

}  // namespace
}  // namespace curdle::site
