// The blocks kind (a 3-D curd as architecture): a stack of voxels, drawn as a plan and an
// elevation, each block a box in 3-D.
#include "kinds/blocks.h"

#include <fmt/format.h>

#include <algorithm>

#include "curdle/overlay.h"
#include "layout/builder.h"
#include "layout/drawing_sheet.h"
#include "layout/legend.h"
#include "recipe/layout_reader.h"

namespace curdle {

double BlocksKind::thickness(const LayoutSpec& spec) const {
  return spec.own<BlocksKeys>().voxel_h;
}

std::string BlocksKind::size_line(const Layout& layout) const {
  return fmt::format("{} x {} x {} voxels of {} x {} x {} mm (w x d x h), {} blocks",
                     layout.view.size[0], layout.view.size[1], layout.view.size[2],
                     drawing_mm(layout.module_w), drawing_mm(layout.module_h),
                     drawing_mm(layout.level_height), layout.elements.size());
}

std::vector<std::string> BlocksKind::keys() const { return {"sheet", "voxel"}; }

std::unique_ptr<KindKeys> BlocksKind::default_keys() const {
  return std::make_unique<BlocksKeys>();
}

CellPlacement BlocksKind::cell_placement(const LayoutSpec& spec, const Box& view) const {
  CellPlacement p;  // voxel (x, y, z) at x w, y d, z h from the view
  const std::array<double, 3> size{spec.module_w, spec.module_h, spec.own<BlocksKeys>().voxel_h};
  for (int d = 0; d < 3; ++d) {
    p.scale[d] = size[d];
    p.origin[d] = -static_cast<double>(view.origin[d]) * size[d];
  }
  return p;
}

std::array<double, 2> BlocksKind::drawing_extent(const LayoutSpec& spec, const Box& view) const {
  // The plan and the elevation side by side (build() lays them out).
  return {2 * view.size[0] * spec.module_w + 2 * std::max(spec.module_w, spec.module_h),
          std::max(view.size[1] * spec.module_h, view.size[2] * spec.own<BlocksKeys>().voxel_h)};
}

void BlocksKind::read(reading::TableReader& r, Design& design, LayoutSpec& spec, bool) const {
  using namespace reading;
  read_value_colours(r, design, spec);
  read_drawing_scale(r, spec);
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
  spec.module_w = v[0], spec.module_h = v[1], spec.own<BlocksKeys>().voxel_h = v[2];
}

Layout BlocksKind::build(const Design& design, const CurdField& field, const Box& view,
                         const LayoutSpec& spec) const {
  Layout layout;
  layout.kind = this;
  layout.combine = spec.combine;
  layout.element_type = std::string(element_noun());
  layout.view = view;
  layout.columns = view.size[0];
  layout.rows = view.size[1];
  layout.module_w = spec.module_w;
  layout.module_h = spec.module_h;
  const double w = spec.module_w, d = spec.module_h, h = spec.own<BlocksKeys>().voxel_h;
  const double plan_w = view.size[0] * w, plan_h = view.size[1] * d, elev_h = view.size[2] * h;
  const double gap = std::max(w, d) * 2;
  layout.level_height = h;
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
        e.form = ElementForm::block;
        e.value = v;
        e.row = y, e.column = x;
        e.cell_x = view.origin[0] + x, e.cell_y = view.origin[1] + y, e.cell_z = view.origin[2] + z;
        e.nominal = Rect{x * w, y * d, w, d};
        e.shape = {e.nominal};
        e.stock_w = w, e.stock_h = d;
        e.key = ElementId{id_letter(), digits, z, y, x, ""};
        e.id = e.key.text();
        layout.elements.push_back(std::move(e));
      }
  // Plan: each column shows its top-most block. Elevation from the front (y = 0 looking
  // towards +y): each position shows the first block met.
  auto id_at = [&](int64_t x, int64_t y, int64_t z) {
    return ElementId{id_letter(), digits, z, y, x, ""}.text();
  };
  BlockViews& views = layout.block_views.emplace();
  for (int64_t y = 0; y < view.size[1]; ++y)
    for (int64_t x = 0; x < view.size[0]; ++x) {
      BlockViews::Cell cell{Rect{x * w, y * d, w, d}, 0, {}, true};
      for (int64_t z = view.size[2] - 1; z >= 0; --z)
        if (const uint16_t v = at(x, y, z)) {
          if (cell.elements.empty()) cell.value = v;
          cell.elements.push_back(id_at(x, y, z));
        }
      if (!cell.elements.empty()) views.cells.push_back(std::move(cell));
    }
  for (int64_t z = 0; z < view.size[2]; ++z)
    for (int64_t x = 0; x < view.size[0]; ++x) {
      BlockViews::Cell cell{Rect{plan_w + gap + x * w, z * h, w, h}, 0, {}, false};
      for (int64_t y = 0; y < view.size[1]; ++y)
        if (const uint16_t v = at(x, y, z)) {
          if (cell.elements.empty()) cell.value = v;
          cell.elements.push_back(id_at(x, y, z));
        }
      if (!cell.elements.empty()) views.cells.push_back(std::move(cell));
    }
  views.captions = {{"plan (top-most block of each column)", Rect{0, 0, plan_w, plan_h}},
                    {"elevation (from the front, y = 0)", Rect{plan_w + gap, 0, plan_w, elev_h}}};

  layout.legend = make_legend(design, spec);
  const std::vector<uint64_t> counts =
      value_counts(field.generated == view ? field : restrict_to(field, view));
  for (uint32_t v = 0; v < counts.size(); ++v) layout.legend[v].count = counts[v];
  return layout;
}

}  // namespace curdle
