#include "site/gltf_reader.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <utility>

#include "curdle/stop.h"
#include "curdle/text.h"

namespace curdle::site {
namespace {

using Matrix = std::array<double, 16>;  // column-major, as glTF
using Point = std::array<double, 3>;    // glTF metres, y up

constexpr double kLevel = 0.001;        // m: how far a face may lie from the lowest level and count
constexpr size_t kMostVisits = 100000;  // nodes placed, counting each place a node is shared

Matrix identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Matrix times(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) m[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return m;
}

// A node's own transform: its matrix, or translation, rotation and scale.
Matrix local(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) {
    Matrix m;
    std::copy(n.matrix.begin(), n.matrix.end(), m.begin());
    return m;
  }
  Matrix t = identity(), r = identity(), s = identity();
  if (n.translation.size() == 3)
    t[12] = n.translation[0], t[13] = n.translation[1], t[14] = n.translation[2];
  if (n.scale.size() == 3) s[0] = n.scale[0], s[5] = n.scale[1], s[10] = n.scale[2];
  if (n.rotation.size() == 4) {
    const double x = n.rotation[0], y = n.rotation[1], z = n.rotation[2], w = n.rotation[3];
    r = {1 - 2 * (y * y + z * z),
         2 * (x * y + z * w),
         2 * (x * z - y * w),
         0,
         2 * (x * y - z * w),
         1 - 2 * (x * x + z * z),
         2 * (y * z + x * w),
         0,
         2 * (x * z + y * w),
         2 * (y * z - x * w),
         1 - 2 * (x * x + y * y),
         0,
         0,
         0,
         0,
         1};
  }
  return times(t, times(r, s));
}

Point transformed(const Matrix& m, const float* p) {
  return {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
          m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
          m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
}

class Reader {
 public:
  Reader(const tinygltf::Model& model, const std::string& file) : model_(model), file_(file) {}

  // Each layer's triangles in the model's frame: a named node (or a scene's root) is a layer
  // holding its own mesh and everything below it, at any depth; `open` are the layers the
  // node lies in.
  void visit(int index, const Matrix& parent, std::vector<size_t>& open, int depth = 0) {
    if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size() || depth > 64)
      fail("a node refers to one it does not have, or nests too deep");
    // Nodes shared down the tree multiply: a hostile file could ask for 2^64 visits.
    if (++visits_ > kMostVisits) fail(fmt::format("places nodes more than {} times", kMostVisits));
    stop_point();
    const tinygltf::Node& n = model_.nodes[static_cast<size_t>(index)];
    const Matrix m = times(parent, local(n));
    const bool named = !n.name.empty() || depth == 0;
    if (named) {
      const std::string name = n.name.empty() ? fmt::format("node {}", index) : shown_name(n.name);
      auto it = std::find(layer_names.begin(), layer_names.end(), name);
      if (it == layer_names.end()) {
        layer_names.push_back(name);
        layers.emplace_back();
        it = layer_names.end() - 1;
      }
      open.push_back(static_cast<size_t>(it - layer_names.begin()));
    }
    if (n.mesh >= 0) {
      std::vector<std::array<Point, 3>> own;
      mesh(static_cast<size_t>(n.mesh), m, own, name_of(n, index));
      for (size_t layer : open) {
        // Each triangle counted once a layer it lies in, so that depth cannot multiply memory.
        if ((placed_ += own.size() * 3) > kMostVertices)
          fail(fmt::format("places more than {} vertices in its layers", kMostVertices));
        layers[layer].insert(layers[layer].end(), own.begin(), own.end());
      }
    }
    for (int c : n.children) visit(c, m, open, depth + 1);
    if (named) open.pop_back();
  }

  std::vector<std::string> layer_names;
  std::vector<std::vector<std::array<Point, 3>>> layers;

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(fmt::format("{}: {}", file_, what));
  }

 private:
  // The bytes of an accessor's elements, checked to lie in its buffer.
  const unsigned char* data(const tinygltf::Accessor& a, size_t element_size,
                            size_t& stride) const {
    if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model_.bufferViews.size())
      fail("an accessor has no buffer view");
    const tinygltf::BufferView& v = model_.bufferViews[static_cast<size_t>(a.bufferView)];
    if (v.buffer < 0 || static_cast<size_t>(v.buffer) >= model_.buffers.size())
      fail("a buffer view has no buffer");
    const std::vector<unsigned char>& b = model_.buffers[static_cast<size_t>(v.buffer)].data;
    stride = v.byteStride ? v.byteStride : element_size;
    const size_t start = v.byteOffset + a.byteOffset;
    if (a.count == 0 || stride < element_size || start > b.size() ||
        (a.count - 1) * stride + element_size > b.size() - start ||
        a.byteOffset + (a.count - 1) * stride + element_size > v.byteLength)
      fail("an accessor runs past its buffer");
    return b.data() + start;
  }

  static std::string name_of(const tinygltf::Node& n, int index) {
    return n.name.empty() ? fmt::format("node {}", index)
                          : fmt::format("node \"{}\"", shown_name(n.name));
  }

  void mesh(size_t index, const Matrix& m, std::vector<std::array<Point, 3>>& out,
            const std::string& node) {
    if (index >= model_.meshes.size()) fail("a node refers to a mesh the file does not have");
    for (const tinygltf::Primitive& p : model_.meshes[index].primitives) {
      if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) continue;  // lines and points: none
      const auto pos = p.attributes.find("POSITION");
      if (pos == p.attributes.end()) continue;
      if (pos->second < 0 || static_cast<size_t>(pos->second) >= model_.accessors.size())
        fail("a mesh refers to positions the file does not have");
      const tinygltf::Accessor& pa = model_.accessors[static_cast<size_t>(pos->second)];
      if (pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || pa.type != TINYGLTF_TYPE_VEC3)
        fail("a mesh's positions are not three floats");
      if ((vertices_ += pa.count) > kMostVertices)
        fail(fmt::format("holds more than {} vertices", kMostVertices));
      size_t ps = 0;
      const unsigned char* pd = data(pa, 12, ps);
      std::vector<Point> points(pa.count);
      for (size_t i = 0; i < pa.count; ++i) {
        float f[3];
        std::memcpy(f, pd + i * ps, 12);
        points[i] = transformed(m, f);
        if (!std::isfinite(points[i][0]) || !std::isfinite(points[i][1]) ||
            !std::isfinite(points[i][2]))
          fail(
              fmt::format("{} has a vertex that is not a finite number (vertex {} of mesh {}); "
                          "the model is damaged: export it again",
                          node, i, index));
      }
      std::vector<size_t> index_list;
      if (p.indices >= 0) {
        if (static_cast<size_t>(p.indices) >= model_.accessors.size())
          fail("a mesh refers to indices the file does not have");
        const tinygltf::Accessor& ia = model_.accessors[static_cast<size_t>(p.indices)];
        const size_t size = ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT     ? 4
                            : ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                            : ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE  ? 1
                                                                                         : 0;
        if (!size || ia.type != TINYGLTF_TYPE_SCALAR) fail("a mesh's indices are not integers");
        if ((vertices_ += ia.count) > kMostVertices)
          fail(fmt::format("holds more than {} vertices", kMostVertices));
        size_t is = 0;
        const unsigned char* id = data(ia, size, is);
        for (size_t i = 0; i < ia.count; ++i) {
          uint32_t v = 0;
          std::memcpy(&v, id + i * is, size);  // little-endian, as glTF is
          if (v >= points.size()) fail("a mesh's index points past its vertices");
          index_list.push_back(v);
        }
      } else {
        for (size_t i = 0; i < points.size(); ++i) index_list.push_back(i);
      }
      for (size_t i = 0; i + 2 < index_list.size(); i += 3)
        out.push_back(
            {points[index_list[i]], points[index_list[i + 1]], points[index_list[i + 2]]});
    }
  }

  const tinygltf::Model& model_;
  const std::string& file_;
  size_t vertices_ = 0, visits_ = 0, placed_ = 0;
};

// Plan millimetres of a glTF point, welded to a tenth of a millimetre.
std::array<int64_t, 2> plan_key(const Point& p) {
  return {std::llround(p[0] * 1e4), std::llround(-p[2] * 1e4)};
}

// The boundary of the horizontal faces at level `low` (the lowest): edges that one such face
// has, chained into loops; empty where they do not chain into one closed outline.
std::vector<Contour> footprint(const std::vector<std::array<Point, 3>>& triangles, double low) {
  std::map<std::pair<std::array<int64_t, 2>, std::array<int64_t, 2>>, int> edges;
  for (const auto& t : triangles) {
    bool flat = true;
    for (const Point& p : t) flat &= std::fabs(p[1] - low) <= kLevel;
    if (!flat) continue;
    for (int k = 0; k < 3; ++k) {
      auto a = plan_key(t[static_cast<size_t>(k)]),
           b = plan_key(t[static_cast<size_t>((k + 1) % 3)]);
      if (a == b) continue;
      if (b < a) std::swap(a, b);
      ++edges[{a, b}];
    }
  }
  std::multimap<std::array<int64_t, 2>, std::array<int64_t, 2>> next;
  for (const auto& [e, count] : edges)
    if (count == 1) next.insert({e.first, e.second}), next.insert({e.second, e.first});
  std::vector<Contour> loops;
  while (!next.empty()) {
    const auto start = next.begin()->first;
    std::array<int64_t, 2> at = start, from{INT64_MIN, INT64_MIN};
    Contour loop;
    for (size_t guard = 0; guard <= edges.size(); ++guard) {
      loop.push_back({static_cast<double>(at[0]) / 10, static_cast<double>(at[1]) / 10, 0});
      auto range = next.equal_range(at);
      auto it = range.first;
      while (it != range.second && it->second == from) ++it;
      if (it == range.second) return {};  // an open chain
      const auto to = it->second;
      next.erase(it);
      for (auto back = next.equal_range(to); back.first != back.second; ++back.first)
        if (back.first->second == at) {
          next.erase(back.first);
          break;
        }
      from = at, at = to;
      if (at == start) break;
    }
    if (at != start) return {};
    loops.push_back(loop);
  }
  return loops;
}

// The loop without points on a straight line between their neighbours (a mesh splits edges).
Contour without_collinear(Contour c) {
  for (size_t k = 0; c.size() > 3 && k < c.size();) {
    const ContourVertex& a = c[(k + c.size() - 1) % c.size()];
    const ContourVertex& b = c[k];
    const ContourVertex& d = c[(k + 1) % c.size()];
    const double cross = (b.x - a.x) * (d.y - b.y) - (b.y - a.y) * (d.x - b.x);
    const double scale = std::hypot(b.x - a.x, b.y - a.y) * std::hypot(d.x - b.x, d.y - b.y);
    if (std::fabs(cross) <= 1e-9 * scale)
      c.erase(c.begin() + static_cast<std::ptrdiff_t>(k));
    else
      ++k;
  }
  return c;
}

// The model's JSON: a .gltf's whole text, a .glb's first chunk.
std::string_view json_of(std::string_view bytes) {
  if (bytes.substr(0, 4) != "glTF") return bytes;
  if (bytes.size() < 20) return {};
  uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return bytes.substr(20, std::min<size_t>(length, bytes.size() - 20));
}

// How deep the JSON's arrays and objects nest, outside its strings, stopping past `most`: the
// JSON parser recurses once a level, and 20,000 levels overflow the stack before it says no.
int json_depth(std::string_view json, int most) {
  int depth = 0, deepest = 0;
  bool in_string = false;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > most) return deepest;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

// A model's JSON nests a few levels (a node's extras perhaps a dozen).
constexpr int kDeepestJson = 64;

}  // namespace

Drawing read_gltf(std::string_view bytes, const std::string& file) {
  if (bytes.size() > kMostDrawingBytes)
    throw InputError(fmt::format("{}: larger than {} MB", file, kMostDrawingBytes >> 20));
  if (json_depth(json_of(bytes), kDeepestJson) > kDeepestJson)
    throw InputError(
        fmt::format("{}: its JSON nests arrays or objects more than {} deep, which no "
                    "model needs; the file is damaged or hostile: export it again",
                    file, kDeepestJson));
  tinygltf::TinyGLTF loader;
  // Nothing outside the file: no buffers or images read from disk, no images decoded.
  tinygltf::FsCallbacks none{};
  none.FileExists = [](const std::string&, void*) { return false; };
  none.ExpandFilePath = [](const std::string& p, void*) { return p; };
  none.ReadWholeFile = [](std::vector<unsigned char>*, std::string* err, const std::string& p,
                          void*) {
    if (err) *err = "refers to a file outside it (" + p + "): embed its buffers";
    return false;
  };
  none.WriteWholeFile = [](std::string*, const std::string&, const std::vector<unsigned char>&,
                           void*) { return false; };
  loader.SetFsCallbacks(none);
  loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int,
                           const unsigned char*, int, void*) { return true; },
                        nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool binary = bytes.substr(0, 4) == "glTF";
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, size, "")
                         : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, "");
  if (!ok)
    throw InputError(fmt::format("{}: not a glTF 2.0 model curdle can read: {}", file,
                                 err.empty() ? "no reason given" : err.substr(0, 300)));
  Reader reader(model, file);
  Drawing d;
  d.format = "glTF";
  d.unit_mm = 1000;  // glTF's unit is the metre
  d.unit_name = "m";
  d.precision = 4;  // a tenth of a millimetre, as the footprint is welded
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (model.scenes.empty() || static_cast<size_t>(scene) >= model.scenes.size())
    reader.fail("holds no scene");
  std::vector<size_t> open;
  for (int root : model.scenes[static_cast<size_t>(scene)].nodes)
    reader.visit(root, identity(), open);
  for (size_t k = 0; k < reader.layers.size(); ++k) {
    const auto& triangles = reader.layers[k];
    if (triangles.empty()) continue;
    const std::string& layer = reader.layer_names[k];
    double low = 1e300, high = -1e300;
    for (const auto& t : triangles)
      for (const Point& p : t) low = std::min(low, p[1]), high = std::max(high, p[1]);
    const std::vector<Contour> loops = footprint(triangles, low);
    if (loops.empty()) {
      Shape s;
      s.layer = layer;
      s.entity = "node";
      s.handle = layer;
      s.fault = fmt::format(
          "the node \"{}\"'s lowest faces (at level {:.3f} m) do not close into an outline: "
          "give the model a floor or ground face, or name a node that has one",
          layer, low);
      s.path = {{0, 0, 0}, {0, 0, 0}};
      d.shapes.push_back(std::move(s));
      continue;
    }
    // Each loop a closed shape on the node's layer: more than one is refused by the site reader
    // with their sizes, or picked by a point, never one chosen silently.
    for (size_t i = 0; i < loops.size(); ++i) {
      Shape s;
      s.layer = layer;
      s.entity = "node";
      s.handle = loops.size() > 1 ? fmt::format("{} loop {}", layer, i + 1) : layer;
      s.path = without_collinear(loops[i]);
      for (ContourVertex& v : s.path) v.x /= 1000, v.y /= 1000;  // mm to the model's metres
      s.closed = true;
      s.height = high - low;
      d.shapes.push_back(std::move(s));
      if (d.shapes.size() > kMostShapes) reader.fail("holds too many nodes");
    }
    d.notes.push_back(fmt::format(
        "{}: {} at level {:.3f} m, {:.3f} m high", layer,
        loops.size() == 1
            ? fmt::format("a footprint of {} corners", without_collinear(loops.front()).size())
            : fmt::format("{} footprint outlines", loops.size()),
        low, high - low));
  }
  return d;
}

}  // namespace curdle::site
