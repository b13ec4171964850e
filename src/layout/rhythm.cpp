#include "layout/rhythm.h"

#include <fmt/format.h>

#include "curdle/overlay.h"
#include "layout/builder.h"

namespace curdle {

void set_rhythm(Layout& layout, const LayoutSpec& spec) {
  std::vector<Element> bays = std::move(layout.elements);
  layout.elements.clear();
  layout.element_type = "fin";
  for (LegendEntry& e : layout.legend) e.count = 0;
  for (Element& e : bays) {
    const double w = spec.rhythm().widths[e.value];
    ++layout.legend[e.value].count;  // bays of each value, as the report counts cells
    if (w <= 0) continue;
    const Rect bay = e.nominal;
    e.shape = {Rect{bay.x + (bay.w - w) / 2, bay.y, w, bay.h}};
    e.stock_w = w, e.stock_h = bay.h;
    e.cut = false;
    e.key = e.key.as('R');
    e.id = e.key.text();
    layout.elements.push_back(std::move(e));
  }
}

Layout stack_blocks(const Design& design, const CurdField& field, const Box& view,
                    const LayoutSpec& spec) {
  Layout layout;
  layout.kind = LayoutKind::blocks;
  layout.combine = spec.combine;
  layout.element_type = "block";
  layout.view = view;
  layout.columns = view.size[0];
  layout.rows = view.size[1];
  layout.module_w = spec.module_w;
  layout.module_h = spec.module_h;
  const double w = spec.module_w, d = spec.module_h, h = spec.blocks().voxel_h;
  const double plan_w = view.size[0] * w, plan_h = view.size[1] * d, elev_h = view.size[2] * h;
  const double gap = std::max(w, d) * 2;
  layout.width = plan_w * 2 + gap;
  layout.height = std::max(plan_h, elev_h);

  const std::vector<uint16_t> values = values_in(field, view);
  auto at = [&](int64_t x, int64_t y, int64_t z) {
    return values[static_cast<size_t>((z * view.size[1] + y) * view.size[0] + x)];
  };
  const int digits =
      static_cast<int>(std::to_string(std::max({view.size[0], view.size[1], view.size[2]})).size());
  for (int64_t z = 0; z < view.size[2]; ++z)
    for (int64_t y = 0; y < view.size[1]; ++y)
      for (int64_t x = 0; x < view.size[0]; ++x) {
        const uint16_t v = at(x, y, z);
        if (!v) continue;
        Element e;
        e.value = v;
        e.row = y, e.column = x;
        e.cell_x = view.origin[0] + x, e.cell_y = view.origin[1] + y, e.cell_z = view.origin[2] + z;
        e.nominal = Rect{x * w, y * d, w, d};
        e.shape = {e.nominal};
        e.stock_w = w, e.stock_h = d;
        e.key = ElementId{'B', digits, z, y, x, ""};
        e.id = e.key.text();
        layout.elements.push_back(std::move(e));
      }
  // Plan: each column shows its top-most block. Elevation from the front (y = 0 looking
  // towards +y): each position shows the first block met.
  auto id_at = [&](int64_t x, int64_t y, int64_t z) {
    return ElementId{'B', digits, z, y, x, ""}.text();
  };
  for (int64_t y = 0; y < view.size[1]; ++y)
    for (int64_t x = 0; x < view.size[0]; ++x) {
      Layout::ViewCell cell{Rect{x * w, y * d, w, d}, 0, {}, true};
      for (int64_t z = view.size[2] - 1; z >= 0; --z)
        if (const uint16_t v = at(x, y, z)) {
          if (cell.elements.empty()) cell.value = v;
          cell.elements.push_back(id_at(x, y, z));
        }
      if (!cell.elements.empty()) layout.views.push_back(std::move(cell));
    }
  for (int64_t z = 0; z < view.size[2]; ++z)
    for (int64_t x = 0; x < view.size[0]; ++x) {
      Layout::ViewCell cell{Rect{plan_w + gap + x * w, z * h, w, h}, 0, {}, false};
      for (int64_t y = 0; y < view.size[1]; ++y)
        if (const uint16_t v = at(x, y, z)) {
          if (cell.elements.empty()) cell.value = v;
          cell.elements.push_back(id_at(x, y, z));
        }
      if (!cell.elements.empty()) layout.views.push_back(std::move(cell));
    }
  layout.captions = {{"plan (top-most block of each column)", Rect{0, 0, plan_w, plan_h}},
                     {"elevation (from the front, y = 0)", Rect{plan_w + gap, 0, plan_w, elev_h}}};

  layout.legend = make_legend(design, spec);
  const std::vector<uint64_t> counts =
      value_counts(field.generated == view ? field : restrict_to(field, view));
  for (uint32_t v = 0; v < counts.size(); ++v) layout.legend[v].count = counts[v];
  return layout;
}

}  // namespace curdle
