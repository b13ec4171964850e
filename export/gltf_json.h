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

// The model's JSON; its one buffer named by `buffer_uri` (empty: the GLB's binary chunk).
std::string gltf_json(const tinygltf::Model& model, const std::string& buffer_uri);

// A binary glTF (.glb): the JSON chunk, then the model's buffer as the binary chunk.
void write_glb_container(std::ostream& out, const tinygltf::Model& model);

}  // namespace curdle
