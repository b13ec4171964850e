// Fuzz target: a site drawing (site/dxf_reader.cpp through site/dxf_groups.cpp, site/svg_reader.cpp
// through libxml2 and SVG++, a massing model through site/gltf_reader.cpp and tinygltf,
// site/site.cpp) read and turned into an outline, openings and zones, as [layout.site] does with
// the layers A (the outline), B (openings) and C (an excluded zone), then laid as a paving floor.
// Any input may be refused with an InputError; none may crash, hang or allocate
// without bound.
#include <cstddef>
#include <cstdint>
#include <string>

#include "curdle/error.h"
#include "layout/zone.h"
#include "site/dxf_reader.h"
#include "site/gltf_reader.h"
#include "site/site.h"
#include "site/svg_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 256 * 1024) return 0;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  // Key by key: GCC 12 warns falsely both of a designated initializer (a member "may be used
  // uninitialized") and of a literal assigned to a string (an overlapping copy).
  curdle::site::LayerMap map;
  const std::string file = "fuzz.dxf", outline = "A", openings = "B", zone = "C", mm = "mm";
  map.file = file;
  map.outline = outline;
  map.openings = {openings};
  map.zones = {{zone, curdle::ZoneRule::exclude, 0}};
  map.unit_mm = size % 2 ? 0.0 : 1.0;  // as the drawing or a recipe says
  map.unit_name = mm;
  try {
    // An SVG begins with markup, a glTF model with its magic or JSON; anything else goes to
    // the DXF reader.
    const size_t first = bytes.find_first_not_of(" \t\r\n");
    const char lead = first != std::string::npos ? bytes[first] : ' ';
    const curdle::site::Drawing drawing =
        lead == '<' ? curdle::site::read_svg(bytes, map.file, {0.05, map.unit_mm})
        : bytes.rfind("glTF", 0) == 0 || lead == '{'
            ? curdle::site::read_gltf(bytes, "fuzz.glb")
            : curdle::site::read_dxf(bytes, map.file, {0.05, map.unit_mm});
    const curdle::site::Site site = curdle::site::site_from(drawing, map);
    // What the recipe reader does next with it: flatten and check every contour.
    (void)curdle::is_simple(curdle::flatten(site.outline, 0.05));
    for (const auto& o : site.openings) (void)curdle::flatten(o, 0.05);
  } catch (const curdle::InputError&) {
  }
  return 0;
}
