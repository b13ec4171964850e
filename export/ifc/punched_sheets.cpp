#include "export/ifc/punched_sheets.h"

#include "export/ifc/ifc_geometry.h"
#include "layout/union.h"
#include "layout/zone.h"

namespace curdle {

std::vector<Ring> opening_rings(const Element& e, double chord_tolerance) {
  if (e.circle) return {ifc_circle_ring(*e.circle, chord_tolerance)};
  std::vector<Ring> rings;
  if (e.outline)
    for (const Outline& part : outline_parts(*e.outline)) rings.push_back(part.rings.front());
  return rings;
}

std::vector<std::vector<Outline>> punched_sheets(const Layout& layout) {
  const std::vector<FabricationSheet>& sheets = layout.sheets();
  std::vector<std::vector<Ring>> holes(sheets.size());
  // Merged openings' islands, per sheet: metal the outline leaves standing.
  std::vector<std::vector<Outline>> islands(sheets.size());
  for (const Element& e : layout.elements) {
    if (e.form != ElementForm::opening || e.sheet < 0) continue;
    const auto k = static_cast<size_t>(e.sheet);
    for (const Ring& ring : opening_rings(e, layout.chord_tolerance)) holes[k].push_back(ring);
    if (e.outline)
      for (const Outline& part : outline_parts(*e.outline))
        for (size_t i = 1; i < part.rings.size(); ++i) islands[k].push_back({{part.rings[i]}, 0});
  }
  std::vector<std::vector<Outline>> punched(sheets.size());
  for (size_t k = 0; k < sheets.size(); ++k) {
    const FabricationSheet& s = sheets[k];
    std::vector<Outline>& parts = punched[k];
    if (s.outline.empty()) {
      parts.push_back({{rect_polygon(s.area)}, s.area.area()});
    } else {
      Outline whole;
      whole.rings = s.outline;
      parts = outline_parts(whole);
    }
    for (Outline& part : parts)
      for (const Ring& hole : holes[k])
        if (contains(part.rings.front(), hole.front()[0], hole.front()[1]))
          part.rings.push_back(hole);
    parts.insert(parts.end(), islands[k].begin(), islands[k].end());
  }
  return punched;
}

}  // namespace curdle
