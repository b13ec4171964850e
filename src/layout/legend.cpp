#include "layout/legend.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <tuple>

#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "layout/layout_kind.h"
#include "layout/piece.h"

namespace curdle {

std::vector<LegendEntry> make_legend(const Design& design, const LayoutSpec& spec) {
  const std::vector<Rgb> blend = value_colours(design.curds);
  std::vector<LegendEntry> legend(blend.size());
  auto packed = [](const Rgb& c) { return uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b; };
  std::map<std::tuple<std::string, uint32_t, std::vector<uint32_t>>, uint32_t> first_alike;
  // A sheet's openings are bought as tool sizes, whatever colour draws them (quantities.csv).
  const bool openings = spec.kind && spec.kind->ground() == Ground::sheet;
  for (uint32_t v = 0; v < blend.size(); ++v) {
    LegendEntry& entry = legend[v];
    entry.value = v;
    entry.label = v < spec.materials.size() ? spec.materials[v] : value_label(v, design.curds);
    entry.colour =
        v < spec.value_colours.size() && spec.value_colours[v] ? *spec.value_colours[v] : blend[v];
    if (spec.combine == Combine::keep) {
      entry.parts = value_parts(design.curds, v);
      if (entry.parts.empty()) entry.parts.push_back(entry.colour);
    }
    std::vector<uint32_t> parts;
    for (const Rgb& c : entry.parts) parts.push_back(packed(c));
    if (openings) parts.clear();
    const uint32_t colour = openings ? 0 : packed(entry.colour);
    entry.same_as = first_alike.try_emplace({entry.label, colour, parts}, v).first->second;
  }
  return legend;
}

std::vector<LegendLine> legend_lines(const std::vector<LegendEntry>& legend) {
  std::vector<LegendLine> lines;
  std::vector<size_t> line_of(legend.size(), SIZE_MAX);
  for (const LegendEntry& e : legend) {
    if (e.count == 0) continue;
    size_t& at = line_of[e.same_as];
    if (at == SIZE_MAX) {
      at = lines.size();
      lines.push_back({&e, {&e}, std::to_string(e.value), 0});
    } else {
      lines[at].values += ", " + std::to_string(e.value);
      std::vector<const LegendEntry*>& looks = lines[at].looks;
      const auto alike = [&e](const LegendEntry* l) {
        return l->colour == e.colour && l->parts == e.parts;
      };
      if (std::none_of(looks.begin(), looks.end(), alike)) looks.push_back(&e);
    }
    lines[at].count += e.count;
  }
  return lines;
}

std::string MaterialLine::text() const {
  if (stands) return fmt::format("{}: {}", label, count);
  std::string line =
      fmt::format("{}: {:.2f} m², {} piece{}", label, area / 1e6, count, count == 1 ? "" : "s");
  if (cut > 0) line += fmt::format(" ({} cut)", cut);
  return line;
}

std::vector<MaterialLine> material_lines(const Layout& layout) {
  std::vector<MaterialLine> lines;
  std::map<std::pair<bool, std::string>, size_t> line_of;
  for (const Element& e : layout.elements) {
    std::string label = piece_material(layout, e);
    if (const PlantingSpec& p = planting_of(layout, e); e.stands) {
      if (!p.species.empty()) label = e.type + " (" + p.species + ")";
      if (p.pit_given()) label += fmt::format(", pit {:g} x {:g} dashed", p.pit[0], p.pit[1]);
    }
    const auto [at, added] = line_of.try_emplace({e.stands, label}, lines.size());
    if (added) lines.push_back({label, piece_colour(layout, e), e.stands});
    MaterialLine& l = lines[at->second];
    l.count += 1;
    l.cut += e.cut ? 1 : 0;
    l.area += e.area();
  }
  std::stable_sort(lines.begin(), lines.end(), [](const MaterialLine& a, const MaterialLine& b) {
    if (a.stands != b.stands) return a.stands;
    return a.stands ? a.label < b.label : a.area > b.area;
  });
  return lines;
}

}  // namespace curdle
