// A layout's legend: one entry per value (its label, colour and, in keep mode, the curds'
// colours side by side), and the lines a legend or key lists, values that lay one product
// together.
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
  std::string values;                  // "2" or "2, 3"
  uint64_t count = 0;
};
std::vector<LegendLine> legend_lines(const std::vector<LegendEntry>& legend);

}  // namespace curdle
