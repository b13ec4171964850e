#include "layout/legend.h"

#include <cstdint>
#include <map>
#include <tuple>

#include "curdle/overlay.h"
#include "curdle/palette.h"

namespace curdle {

std::vector<LegendEntry> make_legend(const Design& design, const LayoutSpec& spec) {
  const std::vector<Rgb> blend = value_colours(design.curds);
  std::vector<LegendEntry> legend(blend.size());
  auto packed = [](const Rgb& c) { return uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b; };
  std::map<std::tuple<std::string, uint32_t, std::vector<uint32_t>>, uint32_t> first_alike;
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
    entry.same_as =
        first_alike.try_emplace({entry.label, packed(entry.colour), parts}, v).first->second;
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
      lines.push_back({&e, std::to_string(e.value), 0});
    } else {
      lines[at].values += ", " + std::to_string(e.value);
    }
    lines[at].count += e.count;
  }
  return lines;
}

}  // namespace curdle
