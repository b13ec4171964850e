// Stepping stones, a layout kind defined in the tests alone, and a run of its recipe.
#pragma once

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "app/outputs.h"
#include "app/run.h"
#include "curdle/error.h"
#include "kinds/registry.h"
#include "layout/builder.h"
#include "layout/layout_kind.h"
#include "recipe/layout_reader.h"
#include "test_support.h"

namespace curdle {

// Stepping stones across a lawn: one stone per cell where a curd survived, inset in its cell.
// The kind's own key: `inset`, the lawn left around each stone.
struct StoneKeys : KindKeysOf<StoneKeys> {
  double inset = 0;
};

class SteppingStones : public LayoutKind {
 public:
  std::string_view name() const override { return "stepping-stones"; }
  std::string_view element_noun() const override { return "stone"; }
  char id_letter() const override { return 'S'; }
  double thickness(const LayoutSpec&) const override { return 40; }
  Ground ground() const override { return Ground::paper; }
  Depiction depiction() const override { return Depiction::shapes; }
  std::vector<std::string> keys() const override { return {"cell", "inset"}; }
  std::unique_ptr<KindKeys> default_keys() const override { return std::make_unique<StoneKeys>(); }
  void read(reading::TableReader& r, Design& design, LayoutSpec& spec, bool) const override {
    const auto cell = reading::read_mm_pair(r, "cell", true);
    spec.module_w = (*cell)[0], spec.module_h = (*cell)[1];
    spec.own<StoneKeys>().inset = reading::read_mm(r, "inset", 50, 0);
    reading::read_value_colours(r, design, spec);
    reading::read_drawing_scale(r, spec);
  }
  Layout build(const Design& design, const CurdField& field, const Box& view,
               const LayoutSpec& spec) const override {
    Layout layout = lay_grid(design, field, view, spec, {});
    count_values(layout, design, spec);
    const double inset = spec.own<StoneKeys>().inset;
    std::erase_if(layout.elements, [](const Element& e) { return e.value == 0; });
    for (Element& e : layout.elements) {
      const Rect& n = e.nominal;
      e.shape = {Rect{n.x + inset, n.y + inset, n.w - 2 * inset, n.h - 2 * inset}};
      e.stock_w = e.shape[0].w, e.stock_h = e.shape[0].h;
    }
    return layout;
  }
};

inline constexpr const char* kStones = R"(name = "stones"
[lattice]
base = 2
dimension = 2
[[curds]]
name = "stone"
probabilities = ["3/4", "2/3", "2/3"]
[field]
cells = [8, 8]
[layout]
kind = "stepping-stones"
cell = [600, 600]
inset = 75
materials = ["lawn", "Granite"]
)";

inline app::Run run_of(const std::string& text, std::vector<std::string> overrides = {}) {
  return test::run_recipe("stones.toml", text, std::move(overrides));
}

inline size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace curdle
