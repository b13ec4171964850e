// Tests of gltf_json.h: the JSON curdle writes for a model says what tinygltf's own writer
// says, value for value, and the GLB container is laid out as glTF 2.0 section 4.4 asks.
#include "export/gltf/gltf_json.h"

#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>

namespace curdle {
namespace {

// A model with every part curdle writes: a mesh of one triangle, two nodes (one a parent with
// extras holding text that JSON must escape), a material and a scene with extras.
tinygltf::Model small_model() {
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.asset.generator = "curdle";
  m.buffers.emplace_back();
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint32_t indices[3] = {0, 1, 2};
  auto& data = m.buffers[0].data;
  data.resize(sizeof positions + sizeof indices + 2);  // an odd length, padded in the GLB
  std::memcpy(data.data(), positions, sizeof positions);
  std::memcpy(data.data() + sizeof positions, indices, sizeof indices);
  tinygltf::BufferView v0, v1;
  v0.buffer = 0, v0.byteLength = sizeof positions, v0.target = TINYGLTF_TARGET_ARRAY_BUFFER;
  v1.buffer = 0, v1.byteOffset = sizeof positions, v1.byteLength = sizeof indices;
  v1.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
  m.bufferViews = {v0, v1};
  tinygltf::Accessor a0, a1;
  a0.bufferView = 0, a0.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT, a0.count = 3;
  a0.type = TINYGLTF_TYPE_VEC3, a0.minValues = {0, 0, 0}, a0.maxValues = {1, 1, 0};
  a1.bufferView = 1, a1.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, a1.count = 3;
  a1.type = TINYGLTF_TYPE_SCALAR;
  m.accessors = {a0, a1};
  tinygltf::Material mat;
  mat.name = "value 1 Grès cérame \"dark\"";
  mat.pbrMetallicRoughness.baseColorFactor = {0.1, 0.2, 0.30000000000000004, 1.0};
  mat.pbrMetallicRoughness.metallicFactor = 0;
  mat.pbrMetallicRoughness.roughnessFactor = 0.8;
  m.materials = {mat};
  tinygltf::Primitive p;
  p.attributes["POSITION"] = 0;
  p.indices = 1, p.material = 0, p.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = "triangle";
  mesh.primitives = {p};
  m.meshes = {mesh};
  tinygltf::Node child, parent;
  child.mesh = 0, child.name = "P-R00-C01";
  child.translation = {1.5, 0.009499999694526196, -1.75}, child.scale = {0.3, 0.02, 0.3};
  tinygltf::Value::Object extras;
  extras["value"] = tinygltf::Value(3);
  extras["curds"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(std::string("a\\b\n"))});
  extras["cut"] = tinygltf::Value(true);
  extras["ratio"] = tinygltf::Value(0.25);
  parent.name = "P-R00-C00", parent.children = {0}, parent.extras = tinygltf::Value(extras);
  m.nodes = {child, parent};
  tinygltf::Scene scene;
  scene.name = "a \"scene\"";
  scene.nodes = {1};
  tinygltf::Value::Object provenance;
  provenance["seed"] = tinygltf::Value(std::string("18446744073709551615"));
  scene.extras = tinygltf::Value(provenance);
  m.scenes = {scene};
  m.defaultScene = 0;
  return m;
}

TEST(GltfJson, SaysWhatTinygltfsOwnWriterSays) {
  const tinygltf::Model m = small_model();
  std::ostringstream theirs;
  tinygltf::TinyGLTF writer;
  ASSERT_TRUE(writer.WriteGltfSceneToStream(&m, theirs, false, false));
  nlohmann::json expected = nlohmann::json::parse(theirs.str());
  expected["buffers"][0] = {{"byteLength", m.buffers[0].data.size()}, {"uri", "layout.bin"}};
  EXPECT_EQ(nlohmann::json::parse(gltf_json(m, "layout.bin")), expected);
}

TEST(GltfJson, TheGlbIsLaidOutAsTheSpecificationAsks) {
  const tinygltf::Model m = small_model();
  std::ostringstream out;
  write_glb_container(out, m);
  const std::string glb = out.str();
  auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, glb.data() + at, 4);
    return v;
  };
  ASSERT_GE(glb.size(), 28u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(u32(4), 2u);
  EXPECT_EQ(u32(8), glb.size());
  const uint32_t json_length = u32(12);
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_EQ(glb.substr(16, 4), "JSON");
  const size_t bin = 20 + json_length;
  EXPECT_EQ(u32(bin) % 4, 0u);
  EXPECT_EQ(glb.substr(bin + 4, 4), std::string("BIN\0", 4));
  EXPECT_EQ(bin + 8 + u32(bin), glb.size());
  // tinygltf, an independent reader, loads it whole.
  tinygltf::Model back;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&back, &err, &warn,
                                          reinterpret_cast<const unsigned char*>(glb.data()),
                                          static_cast<unsigned>(glb.size())))
      << err;
  EXPECT_EQ(back.nodes[1].extras.Get("curds").Get(0).Get<std::string>(), "a\\b\n");
  EXPECT_EQ(back.materials[0].name, m.materials[0].name);
  EXPECT_EQ(back.buffers[0].data.size(), m.buffers[0].data.size());
}

// Nodes kept as text as they are made write the same file as the model's own nodes.
TEST(GltfJson, NodesKeptAsTextWriteTheSameBytes) {
  const tinygltf::Model with_nodes = small_model();
  ASSERT_FALSE(with_nodes.nodes.empty());
  tinygltf::Model without = with_nodes;
  without.nodes.clear();
  NodeText text;
  for (size_t i = 0; i < with_nodes.nodes.size(); ++i)
    EXPECT_EQ(append_node(text, with_nodes.nodes[i]), static_cast<int>(i));
  EXPECT_EQ(text.count, with_nodes.nodes.size());
  EXPECT_EQ(gltf_json(without, "layout.bin", &text), gltf_json(with_nodes, "layout.bin"));
  std::ostringstream streamed;
  write_gltf_json(streamed, without, "layout.bin", text);
  EXPECT_EQ(streamed.str(), gltf_json(with_nodes, "layout.bin"));
  std::ostringstream a, b;
  write_glb_container(a, with_nodes);
  write_glb_container(b, without, &text);
  EXPECT_EQ(a.str(), b.str());
  // No nodes at all: an empty list, still JSON.
  const NodeText none;
  EXPECT_TRUE(nlohmann::json::accept(gltf_json(without, "", &none)));
}

}  // namespace
}  // namespace curdle
