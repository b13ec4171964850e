// A glTF model under construction, as the glTF writer makes it: one buffer appended to,
// materials from sRGB colours, meshes of triangles with their normals, and nodes kept as text
// as they are made (gltf_json.h).
#pragma once

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "curdle/palette.h"
#include "export/gltf/gltf_json.h"
#include "layout/gltf_solids.h"

namespace curdle {

inline double srgb_to_linear(uint8_t c) {
  const double v = c / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// A glTF model under construction: one buffer, appended to.
class ModelBuilder {
 public:
  tinygltf::Model model;
  NodeText nodes;  // as text as they are made: the model's own stay empty

  ModelBuilder() {
    model.asset.version = "2.0";
    model.asset.generator = "curdle";
    model.buffers.emplace_back();
    model.scenes.emplace_back();
    model.defaultScene = 0;
  }

  int add_view(const void* data, size_t bytes, int target) {
    auto& buffer = model.buffers[0].data;
    while (buffer.size() % 4) buffer.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    if (target) view.target = target;
    const auto* p = static_cast<const uint8_t*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size() - 1);
  }

  int add_vec3(const std::vector<Vec3>& v, bool bounds) {
    tinygltf::Accessor a;
    a.bufferView = add_view(v.data(), v.size() * sizeof(Vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = v.size();
    a.type = TINYGLTF_TYPE_VEC3;
    if (bounds) {
      a.minValues = {1e30, 1e30, 1e30};
      a.maxValues = {-1e30, -1e30, -1e30};
      for (const Vec3& p : v)
        for (int i = 0; i < 3; ++i)
          a.minValues[i] = std::min<double>(a.minValues[i], p[i]),
          a.maxValues[i] = std::max<double>(a.maxValues[i], p[i]);
    }
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size() - 1);
  }

  int add_indices(const std::vector<uint32_t>& idx) {
    tinygltf::Accessor a;
    a.bufferView = add_view(idx.data(), idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.count = idx.size();
    a.type = TINYGLTF_TYPE_SCALAR;
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size() - 1);
  }

  int add_material(const std::string& name, const Rgb& c, double metallic, double roughness) {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {srgb_to_linear(c.r), srgb_to_linear(c.g),
                                              srgb_to_linear(c.b), 1.0};
    m.pbrMetallicRoughness.metallicFactor = metallic;
    m.pbrMetallicRoughness.roughnessFactor = roughness;
    model.materials.push_back(m);
    return static_cast<int>(model.materials.size() - 1);
  }

  // A triangle mesh; `positions` with their `normals`, triangles as index triples.
  tinygltf::Primitive primitive(const std::vector<Vec3>& positions,
                                const std::vector<Vec3>& normals,
                                const std::vector<uint32_t>& indices, int material) {
    tinygltf::Primitive p;
    p.attributes["POSITION"] = add_vec3(positions, true);
    p.attributes["NORMAL"] = add_vec3(normals, false);
    p.indices = add_indices(indices);
    p.material = material;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    return p;
  }

  int add_mesh(const std::string& name, std::vector<tinygltf::Primitive> primitives) {
    tinygltf::Mesh m;
    m.name = name;
    m.primitives = std::move(primitives);
    model.meshes.push_back(m);
    return static_cast<int>(model.meshes.size() - 1);
  }

  int add_node(tinygltf::Node node) { return append_node(nodes, node); }
};

}  // namespace curdle
