#include "export/drawing/installer_drawing.h"

#include <algorithm>

#include "curdle/stop.h"
#include "export/drawing/sheet_drawing.h"
#include "layout/legend.h"
#include "layout/piece_rows.h"
#include "layout/title_block.h"

namespace curdle {
namespace {

// Appends `index` to the list of every sheet whose window `bounds` meets: the sheets round the
// grid cells its corners fall in, each asked as its view would ask.
void list_on_sheets(const InstallerPlan& plan, const Rect& bounds, uint32_t index,
                    std::vector<std::vector<uint32_t>>& on) {
  const size_t cols = plan.grid_columns, rows = plan.grid_rows;
  const size_t low = sheet_holding(plan, bounds.x, bounds.y);
  const size_t high = sheet_holding(plan, bounds.right(), bounds.top());
  const size_t c0 = low % cols, r0 = low / cols, c1 = high % cols, r1 = high / cols;
  for (size_t r = r0 ? r0 - 1 : 0; r <= std::min(rows - 1, r1 + 1); ++r)
    for (size_t c = c0 ? c0 - 1 : 0; c <= std::min(cols - 1, c1 + 1); ++c) {
      sheet_drawing::View view;
      view.window = plan.sheets[r * cols + c].window;
      if (view.shows(bounds)) on[r * cols + c].push_back(index);
    }
}

}  // namespace

InstallerDrawing installer_set(const Layout& layout, const InstallerPlan& plan) {
  InstallerDrawing set{plan, laying_extents(layout),
                       std::vector<SheetContents>(plan.sheets.size())};
  set.title = title_lines(layout);
  // Each piece belongs to the sheet that holds its centre, as its label does.
  auto sheet_holding_centre = [&](const Rect& b) {
    return sheet_holding(plan, b.x + b.w / 2, b.y + b.h / 2);
  };
  if (plan.sheets.empty()) return set;
  const size_t sheets = plan.sheets.size();
  set.elements_on.resize(sheets);
  set.pieces_on.resize(sheets);
  set.labels_on.resize(sheets);
  for (uint32_t i = 0; i < plan.pieces.size(); ++i) {
    ++set.contents[sheet_holding_centre(plan.pieces[i].bounds)].pieces;
    list_on_sheets(plan, plan.pieces[i].bounds, i, set.pieces_on);
  }
  for (uint32_t i = 0; i < plan.labels.size(); ++i)
    if (plan.labels[i].sheet < sheets) set.labels_on[plan.labels[i].sheet].push_back(i);
  const bool elements = !layout.fabrication;  // else the pieces are fabrication sheets
  for (uint32_t i = 0; i < layout.elements.size(); ++i) {
    stop_point();
    const Element& e = layout.elements[i];
    const Rect bounds = laid_bounds(e);
    list_on_sheets(plan, bounds, i, set.elements_on);
    SheetContents& c = set.contents[sheet_holding_centre(label_bounds(e))];
    if (elements) {
      c.row0 = std::min(c.row0, e.row), c.row1 = std::max(c.row1, e.row);
      c.column0 = std::min(c.column0, e.column), c.column1 = std::max(c.column1, e.column);
    }
    c.backing += needs_backing(layout, e);
    // Values that lay the same product are one line, hatched alike (LegendEntry::same_as).
    const uint32_t value = e.type.empty() ? layout.legend[e.value].same_as : 0;
    SheetContents::KeyLine& line = c.key[{piece_material(layout, e), value}];
    const LegendEntry& l = layout.legend[e.value];
    const std::vector<Rgb> look =
        e.type.empty() && layout.combine == Combine::keep && l.parts.size() > 1
            ? l.parts
            : std::vector<Rgb>{piece_colour(layout, e)};
    if (line.count++ == 0) line.value = l.same_as;
    // Each look the line's pieces are drawn in, side by side in the key.
    if (std::find(line.looks.begin(), line.looks.end(), look) == line.looks.end()) {
      line.looks.push_back(look);
      line.swatch.insert(line.swatch.end(), look.begin(), look.end());
    }
  }
  return set;
}

}  // namespace curdle
