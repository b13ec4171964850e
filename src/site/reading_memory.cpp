#include "site/reading_memory.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstring>

#include "site/drawing.h"

namespace curdle::site {
namespace {

// What each reader holds a piece, bytes, from the peaks measured under /usr/bin/time (the
// ratio of each estimate to its peak is in tests/reading_memory_test.cpp): a DXF group read as
// a code and its text; a shape with its names and contour; a vertex of a contour and its
// flattened copy; an XML element in libxml2's tree; a JSON value in tinygltf's own tree.
constexpr uint64_t kGroupBytes = 64;
constexpr uint64_t kShapeBytes = 800;
constexpr uint64_t kVertexBytes = 64;
constexpr uint64_t kElementBytes = 300;
constexpr uint64_t kJsonValueBytes = 256;
// Path data: a vertex takes at least four bytes of text ("1 2 "); held as a contour and its
// flattened copy.
constexpr uint64_t kPathBytesPerTextByte = 8;

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

uint64_t dxf_memory(std::string_view bytes) {
  uint64_t groups = 0, entities = 0, vertices = 0;
  size_t at = 0;
  while (at < bytes.size()) {
    const size_t code_end = std::min(bytes.find('\n', at), bytes.size());
    const std::string_view code = trimmed(bytes.substr(at, code_end - at));
    const size_t value_end =
        std::min(bytes.find('\n', std::min(code_end + 1, bytes.size())), bytes.size());
    at = value_end + 1;
    ++groups;
    if (code == "0") ++entities;
    if (code == "10" || code == "11") ++vertices;
  }
  return groups * kGroupBytes + std::min<uint64_t>(entities, kMostShapes) * kShapeBytes +
         vertices * kVertexBytes;
}

uint64_t svg_memory(std::string_view bytes) {
  const auto elements = static_cast<uint64_t>(std::count(bytes.begin(), bytes.end(), '<'));
  return elements * kElementBytes + std::min<uint64_t>(elements, kMostShapes) * kShapeBytes +
         bytes.size() * kPathBytesPerTextByte;
}

// A glb's JSON chunk (its length as the header says, held to the file), or the whole .gltf.
std::string_view gltf_json(std::string_view bytes) {
  if (bytes.size() < 20 || bytes.substr(0, 4) != "glTF") return bytes;
  uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);  // little-endian, as glb is and the machine is
  return bytes.substr(20, std::min<size_t>(length, bytes.size() - 20));
}

uint64_t gltf_memory(std::string_view bytes) {
  const std::string_view json = gltf_json(bytes);
  uint64_t values = 1;
  for (const char c : json) values += c == ',' || c == '[' || c == '{';
  return values * kJsonValueBytes + (bytes.size() - json.size());
}

std::string mebibytes(uint64_t bytes) {
  return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / 1048576.0);
}

}  // namespace

uint64_t reading_memory(std::string_view bytes, const std::string& name) {
  std::string ending = name.size() >= 4 ? name.substr(name.size() - 4) : name;
  for (char& c : ending) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  // The bytes themselves, and the copy a reader may make of them (a data URI decoded, a string).
  const uint64_t held = 2 * static_cast<uint64_t>(bytes.size());
  if (ending == ".glb" || ending == "gltf") return held + gltf_memory(bytes);
  if (ending == ".svg") return held + svg_memory(bytes);
  return held + dxf_memory(bytes);
}

void check_reading_memory(std::string_view bytes, const std::string& name, uint64_t limit,
                          const std::string& hint) {
  if (limit == 0) return;
  const uint64_t need = reading_memory(bytes, name);
  if (need <= limit) return;
  throw InputError(fmt::format(
      "{}: reading this drawing of {} could take up to {}, above the memory limit of {}; {}, or "
      "keep in the drawing only the layers the surface needs",
      name, mebibytes(bytes.size()), mebibytes(need), mebibytes(limit),
      hint.empty() ? "raise the limit" : hint));
}

}  // namespace curdle::site
