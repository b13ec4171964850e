// [layout] of kinds "rhythm" (a 1-D line of bays, fins whose width follows the value) and
// "blocks" (3-D voxels drawn as plan and elevation).
#include <cmath>

#include "recipe/layout_reader.h"

namespace curdle::reading {

void read_blocks(TableReader& r, LayoutSpec& spec) {
  const toml::node* n = r.get("voxel");
  const toml::array* a = n ? n->as_array() : nullptr;
  std::array<double, 3> v{3000, 3000, 3000};
  if (n) {
    bool ok = a && a->size() == 3;
    for (size_t i = 0; ok && i < 3; ++i) {
      const auto x = finite_number(a->get(i));
      ok = x && *x > 0 && *x <= 1e6;
      if (ok) v[i] = *x;
    }
    if (!ok) r.fail("voxel", "must be [width, depth, height] in millimetres, each above 0");
  }
  spec.module_w = v[0], spec.module_h = v[1], spec.blocks().voxel_h = v[2];
}

void read_rhythm(TableReader& r, Design& design, LayoutSpec& spec, bool field_given) {
  const size_t values = size_t{1} << design.curds.size();
  read_value_colours(r, design, spec);
  read_drawing_scale(r, spec);
  spec.module_w = read_mm(r, "bay", 600, 1);
  spec.module_h = read_mm(r, "height", 3000, 1);
  const auto origin =
      read_string(r, "origin", "\"bottom-left\" or \"bottom-right\"").value_or("bottom-left");
  if (origin != "bottom-left" && origin != "bottom-right")
    r.fail("origin", "must be \"bottom-left\" or \"bottom-right\" for a line");
  spec.origin = origin == "bottom-left" ? Corner::bottom_left : Corner::bottom_right;

  const toml::node* n = r.get("widths");
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->size() != values)
    r.fail("widths", "must give one element width in mm per value (" + std::to_string(values) +
                         "), value 0 first; 0 leaves a bay empty");
  for (size_t v = 0; v < a->size(); ++v) {
    const auto x = finite_number(a->get(v));
    if (!x || *x < 0 || *x > spec.module_w)
      r.fail_node(*a->get(v), "layout.widths." + std::to_string(v),
                  "must be a width from 0 to the bay (" +
                      std::to_string(static_cast<int>(spec.module_w)) + " mm)");
    spec.rhythm().widths.push_back(*x);
  }
  if (r.get("length")) {
    const double length = read_mm(r, "length", 0, 1);
    spec.size = std::array<double, 2>{length, spec.module_h};
    const int64_t bays = static_cast<int64_t>(std::ceil(length / spec.module_w - 1e-9));
    // A larger field is a curd from which a segment of `bays` becomes the line.
    if (field_given && design.field.size[0] < bays)
      r.fail("length", "needs " + std::to_string(bays) + " bays but field.cells is " +
                           std::to_string(design.field.size[0]) +
                           "; leave field.cells out, or make it at least that large");
    if (!field_given) design.field.size[0] = bays;
  }
}

}  // namespace curdle::reading
