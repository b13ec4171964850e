// Rhythm (a 1-D curd as architecture): a line of bays — fins, mullions, the bays of a
// colonnade — whose element widths and colours follow the values.
#pragma once

#include <optional>
#include <vector>

#include "building/building.h"
#include "layout/layout.h"

namespace curdle {

struct RhythmKeys : KindKeysOf<RhythmKeys> {
  std::vector<double> widths;  // per value, the element's width in its bay, mm; 0: no element
  // [layout.building]: the line runs round a building's plan (or along a path), the fins
  // standing off its face, as high as the building.
  std::optional<BuildingKeys> building;
  std::optional<Envelope> envelope;
};

class RhythmKind : public LayoutKind {
 public:
  std::string_view name() const override { return "rhythm"; }
  const Envelope* envelope(const LayoutSpec& spec) const override;
  std::string_view element_noun() const override { return "bay"; }
  std::string_view legend_unit() const override { return "bay"; }
  char id_letter() const override { return 'B'; }  // bays; their elements become "R-..."
  int dimension() const override { return 1; }
  double thickness(const LayoutSpec&) const override { return 300; }  // fins stand out
  bool upright() const override { return true; }
  bool stands_off() const override { return true; }
  Finish finish() const override { return {0.9, 0.8}; }
  Ground ground() const override { return Ground::paper; }
  Depiction depiction() const override { return Depiction::shapes; }
  std::string size_line(const Layout& layout) const override;
  std::vector<std::string> keys() const override;
  std::unique_ptr<KindKeys> default_keys() const override;
  void read(reading::TableReader& r, Design& design, LayoutSpec& spec,
            bool field_given) const override;
  Layout build(const Design& design, const CurdField& field, const Box& view,
               const LayoutSpec& spec) const override;
  CellPlacement cell_placement(const LayoutSpec& spec, const Box& view) const override;
};

// Narrows each bay's element to its value's width, centred in the bay; drops zero widths.
void set_rhythm(Layout& layout, const LayoutSpec& spec);

// Stands the fins round a building's envelope: its frames place them, and a fin whose width
// would cross a corner is left out, with a note.
void stand_round(Layout& layout, const Envelope& envelope);

}  // namespace curdle
