// glTF's JSON and its binary container, written from a tinygltf::Model by curdle itself.
// tinygltf serialises a model through a JSON document of its own: for a million tiles that was
// 8 s with no point to stop at and a peak of 4.3 GB. Written here as text, element by element,
// with a stop point per node, for the parts of glTF 2.0 that curdle's models use (asset, scene,
// nodes, meshes, accessors, buffer views, one buffer, materials and extras).
#pragma once

#include <tiny_gltf.h>

#include <ostream>
#include <string>

namespace curdle {

// Nodes kept as their JSON text as they are made, instead of in the model: a million tiles'
// tinygltf::Node objects with their extras took 2.9 KB each, sixteen times the file they make.
struct NodeText {
  std::string json;  // the nodes, comma-separated, without the brackets
  size_t count = 0;
};
// Appends `node` (as tinygltf would hold it) and returns its index.
int append_node(NodeText& nodes, const tinygltf::Node& node);

// The model's JSON; its one buffer named by `buffer_uri` (empty: the GLB's binary chunk). Its
// nodes are `nodes` when given (the model's own then empty), else the model's.
std::string gltf_json(const tinygltf::Model& model, const std::string& buffer_uri,
                      const NodeText* nodes = nullptr);

// The same JSON written to `out`, the nodes' text where it is (never copied).
void write_gltf_json(std::ostream& out, const tinygltf::Model& model, const std::string& buffer_uri,
                     const NodeText& nodes);

// A binary glTF (.glb): the JSON chunk, then the model's buffer as the binary chunk.
void write_glb_container(std::ostream& out, const tinygltf::Model& model,
                         const NodeText* nodes = nullptr);

}  // namespace curdle
