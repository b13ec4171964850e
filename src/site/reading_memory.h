// What reading a drawing may cost in memory, estimated from its bytes before any parser sees
// them, so that a drawing too large for the caller's memory limit is refused before it is
// parsed (a 20 MB glTF whose JSON holds ten million numbers takes 2 GB inside tinygltf). The
// estimate counts what each reader holds: DXF groups, entities and vertices; SVG elements (the
// XML tree and the shapes) and path data; glTF JSON values and buffers. It is an upper bound,
// measured against the readers' peaks (tests/reading_memory_test.cpp says by how much).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace curdle::site {

// Bytes at most that reading `bytes` as `name` says (.dxf, .svg, .glb, .gltf) may take.
uint64_t reading_memory(std::string_view bytes, const std::string& name);

// InputError when reading_memory is above `limit` bytes (0: no limit): naming the file, its size,
// the estimate and the limit, and `hint`, how the caller raises it ("raise --max-memory").
void check_reading_memory(std::string_view bytes, const std::string& name, uint64_t limit,
                          const std::string& hint);

}  // namespace curdle::site
