// A layout's legend: one entry per value (its label, colour and, in keep mode, the curds'
// colours side by side), and the lines a legend or key lists, values that lay one product
// together; a park's, what it plants and builds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "curdle/curd.h"
#include "layout/layout.h"

namespace curdle {

// One legend entry per value: label, colour (the spec's, or the blend of the curds'), and in
// keep mode the colours shown side by side; `same_as` the first value with the same label,
// colour and parts. Counts are left at zero.
std::vector<LegendEntry> make_legend(const Design& design, const LayoutSpec& spec);

// The lines of a legend: one per product, each with the values it covers ("2, 3") and their
// summed count, in value order of their first; values with no element are left out.
struct LegendLine {
  const LegendEntry* entry = nullptr;  // the first value's entry: label, colour, parts
  // Every look the product is drawn in (the first value's, then each other colour or set of
  // parts): a sheet's openings of one size are one line however their values are coloured.
  std::vector<const LegendEntry*> looks;
  std::string values;  // "2" or "2, 3"
  uint64_t count = 0;
};
std::vector<LegendLine> legend_lines(const std::vector<LegendEntry>& legend);

// What a park plants and builds (its value combinations say nothing to a contractor): one line a
// material, the standing objects first (how many), then the surfaces (area laid), largest first.
struct MaterialLine {
  std::string label;  // the object's type and species, or the surface's material
  Rgb colour;
  bool stands = false;
  uint64_t count = 0, cut = 0;  // pieces (objects: how many stand), cut ones
  double area = 0;              // laid, mm²
  std::string text() const;     // "tree (Tilia cordata): 13", "gravel: 204.85 m², 15 pieces"
};
std::vector<MaterialLine> material_lines(const Layout& layout);

}  // namespace curdle
