#include "export/gltf/gltf_json.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <stdexcept>

#include "curdle/check.h"
#include "curdle/stop.h"

namespace curdle {
namespace {

// JSON text appended to one string: keys in the order tinygltf wrote them (alphabetical), so
// that files keep their shape.
class JsonText {
 public:
  std::string text;

  void open(char c) {
    comma();
    text += c;
    first_ = true;
  }
  void close(char c) {
    text += c;
    first_ = false;
  }
  void key(const char* k) {
    comma();
    text += '"';
    text += k;
    text += "\":";
    first_ = true;  // the value follows without a comma
  }
  void string(const std::string& s) {
    comma();
    text += '"';
    for (const char c : s) {
      const auto u = static_cast<unsigned char>(c);
      if (c == '"' || c == '\\') {
        text += '\\';
        text += c;
      } else if (u < 0x20) {
        text += fmt::format("\\u{:04x}", u);
      } else {
        text += c;  // UTF-8 as it is: names are checked for it where they are read
      }
    }
    text += '"';
  }
  void number(double v) {
    if (!std::isfinite(v)) throw std::runtime_error("a glTF number is not finite");
    comma();
    fmt::format_to(std::back_inserter(text), "{}", v);
  }
  void integer(int64_t v) {
    comma();
    fmt::format_to(std::back_inserter(text), "{}", v);
  }
  // Text that is already JSON (a value).
  void raw(const std::string& json) {
    comma();
    text += json;
  }
  void boolean(bool v) {
    comma();
    text += v ? "true" : "false";
  }
  void numbers(const std::vector<double>& v) {
    open('[');
    for (const double x : v) number(x);
    close(']');
  }
  void integers(const std::vector<int>& v) {
    open('[');
    for (const int x : v) integer(x);
    close(']');
  }

 private:
  void comma() {
    if (!first_) text += ',';
    first_ = false;
  }
  bool first_ = true;
};

void value(JsonText& j, const tinygltf::Value& v) {
  if (v.IsBool()) {
    j.boolean(v.Get<bool>());
  } else if (v.IsInt()) {
    j.integer(v.Get<int>());
  } else if (v.IsReal()) {
    j.number(v.Get<double>());
  } else if (v.IsString()) {
    j.string(v.Get<std::string>());
  } else if (v.IsArray()) {
    j.open('[');
    for (size_t i = 0; i < v.ArrayLen(); ++i) value(j, v.Get(static_cast<int>(i)));
    j.close(']');
  } else if (v.IsObject()) {
    j.open('{');
    for (const auto& [k, item] : v.Get<tinygltf::Value::Object>()) {
      j.key(k.c_str());
      value(j, item);
    }
    j.close('}');
  } else {
    j.open('{');  // null or binary: curdle writes neither; an empty object keeps JSON valid
    j.close('}');
  }
}

bool has_extras(const tinygltf::Value& v) { return v.IsObject() || v.IsArray() || v.IsString(); }

const char* accessor_type(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    case TINYGLTF_TYPE_MAT4:
      return "MAT4";
    default:
      CHECK(false, "an accessor of a type curdle does not write");
      return "";
  }
}

void accessors(JsonText& j, const tinygltf::Model& m) {
  j.key("accessors");
  j.open('[');
  for (const tinygltf::Accessor& a : m.accessors) {
    j.open('{');
    j.key("bufferView"), j.integer(a.bufferView);
    if (a.byteOffset) j.key("byteOffset"), j.integer(static_cast<int64_t>(a.byteOffset));
    j.key("componentType"), j.integer(a.componentType);
    j.key("count"), j.integer(static_cast<int64_t>(a.count));
    if (!a.maxValues.empty()) j.key("max"), j.numbers(a.maxValues);
    if (!a.minValues.empty()) j.key("min"), j.numbers(a.minValues);
    j.key("type"), j.string(accessor_type(a.type));
    j.close('}');
  }
  j.close(']');
}

void buffer_views(JsonText& j, const tinygltf::Model& m) {
  j.key("bufferViews");
  j.open('[');
  for (const tinygltf::BufferView& v : m.bufferViews) {
    j.open('{');
    j.key("buffer"), j.integer(v.buffer);
    j.key("byteLength"), j.integer(static_cast<int64_t>(v.byteLength));
    if (v.byteOffset) j.key("byteOffset"), j.integer(static_cast<int64_t>(v.byteOffset));
    if (v.byteStride) j.key("byteStride"), j.integer(static_cast<int64_t>(v.byteStride));
    if (v.target) j.key("target"), j.integer(v.target);
    j.close('}');
  }
  j.close(']');
}

void materials(JsonText& j, const tinygltf::Model& m) {
  j.key("materials");
  j.open('[');
  for (const tinygltf::Material& mat : m.materials) {
    j.open('{');
    if (!mat.name.empty()) j.key("name"), j.string(mat.name);
    const tinygltf::PbrMetallicRoughness& pbr = mat.pbrMetallicRoughness;
    j.key("pbrMetallicRoughness");
    j.open('{');
    j.key("baseColorFactor"), j.numbers(pbr.baseColorFactor);
    j.key("metallicFactor"), j.number(pbr.metallicFactor);
    j.key("roughnessFactor"), j.number(pbr.roughnessFactor);
    j.close('}');
    if (mat.alphaMode != "OPAQUE") j.key("alphaMode"), j.string(mat.alphaMode);
    if (mat.doubleSided) j.key("doubleSided"), j.boolean(true);
    j.close('}');
  }
  j.close(']');
}

void meshes(JsonText& j, const tinygltf::Model& m) {
  j.key("meshes");
  j.open('[');
  for (const tinygltf::Mesh& mesh : m.meshes) {
    stop_point();
    j.open('{');
    if (!mesh.name.empty()) j.key("name"), j.string(mesh.name);
    j.key("primitives");
    j.open('[');
    for (const tinygltf::Primitive& p : mesh.primitives) {
      j.open('{');
      j.key("attributes");
      j.open('{');
      for (const auto& [name, accessor] : p.attributes) j.key(name.c_str()), j.integer(accessor);
      j.close('}');
      if (p.indices >= 0) j.key("indices"), j.integer(p.indices);
      if (p.material >= 0) j.key("material"), j.integer(p.material);
      j.key("mode"), j.integer(p.mode);
      j.close('}');
    }
    j.close(']');
    j.close('}');
  }
  j.close(']');
}

void node(JsonText& j, const tinygltf::Node& n) {
  j.open('{');
  if (!n.children.empty()) j.key("children"), j.integers(n.children);
  if (has_extras(n.extras)) j.key("extras"), value(j, n.extras);
  if (!n.matrix.empty()) j.key("matrix"), j.numbers(n.matrix);
  if (n.mesh >= 0) j.key("mesh"), j.integer(n.mesh);
  if (!n.name.empty()) j.key("name"), j.string(n.name);
  if (!n.rotation.empty()) j.key("rotation"), j.numbers(n.rotation);
  if (!n.scale.empty()) j.key("scale"), j.numbers(n.scale);
  if (!n.translation.empty()) j.key("translation"), j.numbers(n.translation);
  j.close('}');
}

// With `split`, the nodes are left for the caller to put at *split, between '[' and ']'.
void nodes(JsonText& j, const tinygltf::Model& m, size_t* split) {
  j.key("nodes");
  if (split) {
    j.raw("[");
    *split = j.text.size();
    j.text += ']';
    return;
  }
  j.open('[');
  for (const tinygltf::Node& n : m.nodes) {
    stop_point();
    node(j, n);
  }
  j.close(']');
}

void scenes(JsonText& j, const tinygltf::Model& m) {
  if (m.defaultScene >= 0) j.key("scene"), j.integer(m.defaultScene);
  j.key("scenes");
  j.open('[');
  for (const tinygltf::Scene& s : m.scenes) {
    j.open('{');
    if (has_extras(s.extras)) j.key("extras"), value(j, s.extras);
    if (!s.name.empty()) j.key("name"), j.string(s.name);
    j.key("nodes"), j.integers(s.nodes);
    j.close('}');
  }
  j.close(']');
}

}  // namespace

int append_node(NodeText& nodes, const tinygltf::Node& n) {
  stop_point();
  JsonText j;
  node(j, n);
  if (nodes.count) nodes.json += ',';
  nodes.json += j.text;
  return static_cast<int>(nodes.count++);
}

namespace {

// The model's JSON; with `split`, without its nodes, which go at *split.
std::string model_json(const tinygltf::Model& model, const std::string& buffer_uri, size_t* split) {
  CHECK(model.buffers.size() == 1 && model.extensionsUsed.empty() && model.images.empty() &&
            model.textures.empty() && model.animations.empty() && model.skins.empty() &&
            model.cameras.empty(),
        "a glTF model with parts curdle does not write");
  JsonText j;
  j.open('{');
  accessors(j, model);
  j.key("asset");
  j.open('{');
  j.key("generator"), j.string(model.asset.generator);
  j.key("version"), j.string(model.asset.version);
  j.close('}');
  buffer_views(j, model);
  j.key("buffers");
  j.open('[');
  j.open('{');
  j.key("byteLength"), j.integer(static_cast<int64_t>(model.buffers[0].data.size()));
  if (!buffer_uri.empty()) j.key("uri"), j.string(buffer_uri);
  j.close('}');
  j.close(']');
  materials(j, model);
  meshes(j, model);
  nodes(j, model, split);
  scenes(j, model);
  j.close('}');
  return std::move(j.text);
}

}  // namespace

std::string gltf_json(const tinygltf::Model& model, const std::string& buffer_uri,
                      const NodeText* nodes) {
  size_t split = 0;
  std::string json = model_json(model, buffer_uri, nodes ? &split : nullptr);
  if (nodes) json.insert(split, nodes->json);
  return json;
}

void write_gltf_json(std::ostream& out, const tinygltf::Model& model, const std::string& buffer_uri,
                     const NodeText& nodes) {
  size_t split = 0;
  const std::string json = model_json(model, buffer_uri, &split);
  out.write(json.data(), static_cast<std::streamsize>(split));
  out.write(nodes.json.data(), static_cast<std::streamsize>(nodes.json.size()));
  out.write(json.data() + split, static_cast<std::streamsize>(json.size() - split));
}

void write_glb_container(std::ostream& out, const tinygltf::Model& model, const NodeText* nodes) {
  // GLB (glTF 2.0, section 4.4): a 12-byte header, then chunks of 4-byte-aligned length: the
  // JSON padded with spaces, the buffer padded with zeros. The nodes' text is written where it
  // is, never copied into the JSON.
  size_t split = 0;
  std::string json = model_json(model, "", nodes ? &split : nullptr);
  const std::string& between = nodes ? nodes->json : std::string();
  const size_t json_size = json.size() + between.size();
  json.append((4 - json_size % 4) % 4, ' ');
  const std::vector<unsigned char>& bin = model.buffers[0].data;
  const size_t bin_padded = bin.size() + (4 - bin.size() % 4) % 4;
  const uint64_t total = 12 + 8 + json.size() + between.size() + (bin.empty() ? 0 : 8 + bin_padded);
  if (total > UINT32_MAX)
    throw std::runtime_error("the layout's glTF would be over 4 GiB, beyond what a .glb holds");
  auto u32 = [&](uint64_t v) {
    const char b[4] = {static_cast<char>(v), static_cast<char>(v >> 8), static_cast<char>(v >> 16),
                       static_cast<char>(v >> 24)};
    out.write(b, 4);
  };
  out.write("glTF", 4);
  u32(2);
  u32(total);
  u32(json.size() + between.size());
  out.write("JSON", 4);
  out.write(json.data(), static_cast<std::streamsize>(split));
  out.write(between.data(), static_cast<std::streamsize>(between.size()));
  out.write(json.data() + split, static_cast<std::streamsize>(json.size() - split));
  if (bin.empty()) return;
  u32(bin_padded);
  out.write("BIN\0", 4);
  out.write(reinterpret_cast<const char*>(bin.data()), static_cast<std::streamsize>(bin.size()));
  out.write("\0\0\0", static_cast<std::streamsize>(bin_padded - bin.size()));
}

}  // namespace curdle
