// Sheet 1's legend (drawing_set.h): what each line counts, from the layout's elements.
#include <fmt/format.h>

#include <map>

#include "curdle/stop.h"
#include "export/drawing/drawing_set.h"
#include "layout/layout_kind.h"
#include "layout/legend.h"
#include "layout/piece_rows.h"
#include "layout/title_block.h"

namespace curdle {
namespace {

struct Quantity {
  uint64_t whole = 0, cut = 0;
  double area = 0;  // m2
};

}  // namespace

std::vector<std::pair<std::vector<Rgb>, std::string>> sheet_legend(const Layout& layout) {
  std::vector<std::pair<std::vector<Rgb>, std::string>> rows;
  if (layout.kind->depiction() == Depiction::objects) {
    for (const MaterialLine& l : material_lines(layout)) rows.push_back({{l.colour}, l.text()});
    return rows;
  }
  std::map<uint32_t, Quantity> quantities;
  for (const Element& e : layout.elements) {
    stop_point();
    Quantity& q = quantities[layout.legend[e.value].same_as];  // by legend line
    (e.cut ? q.cut : q.whole) += 1;
    q.area += e.area() / 1e6;
  }
  for (const LegendLine& legend_line : legend_lines(layout.legend)) {
    const LegendEntry& e = *legend_line.entry;
    const Quantity q = quantities.count(e.value) ? quantities[e.value] : Quantity{};
    std::string line = fmt::format("{} {}: {}", legend_line.values, e.label,
                                   legend_count(layout, legend_line.count));
    if (q.cut) line += fmt::format(" ({} cut)", q.cut);
    if (q.area > 0 && layout.kind->ground() != Ground::sheet)  // not a sheet's holes
      line += fmt::format(", {:.2f} m²", q.area);
    std::vector<Rgb> swatch;  // each look the line's values are drawn in, side by side
    for (const LegendEntry* look : legend_line.looks) {
      if (look->parts.size() > 1 && layout.combine == Combine::keep)
        swatch.insert(swatch.end(), look->parts.begin(), look->parts.end());
      else
        swatch.push_back(look->colour);
    }
    rows.push_back({swatch, line});
  }
  if (layout.envelope) {  // a building's units by part, as quantities.csv orders them
    std::map<std::string, uint64_t> by_part;
    for (const Element& e : layout.elements) ++by_part[element_type_of(layout, e)];
    if (by_part.size() > 1)
      for (const auto& [part, n] : by_part)
        rows.push_back({{}, fmt::format("all tones, {}: {}", part, n)});
  }
  // A one-brick wall: the backing behind its face, unseen but laid.
  if (const WallBacking* backed = layout.backing()) {
    size_t backing = 0, cut = 0;
    for (const Element& e : layout.elements)
      if (needs_backing(layout, e)) ++backing, cut += e.cut;
    rows.push_back({{kBackingColour},
                    fmt::format("behind the face, {}: {} ({} cut)", backed->material,
                                legend_count(layout, backing), cut)});
  }
  return rows;
}

}  // namespace curdle
