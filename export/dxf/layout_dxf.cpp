#include "export/dxf/layout_dxf.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "curdle/stop.h"
#include "export/dxf/dxf_document.h"
#include "layout/piece.h"
#include "layout/wkt.h"

namespace curdle {
namespace {

constexpr Rgb kInk{0, 0, 0};

std::string layer_of(const Layout& layout, const Element& e) {
  if (e.circle && e.form == ElementForm::opening) return hole_layer(e.circle->d);
  if (e.outline && e.form == ElementForm::opening) return "OPENING_OUTLINE";
  const std::string& material = piece_material(layout, e);
  if (e.form == ElementForm::block)
    return fmt::format("L{} {}", e.cell_z - layout.view.origin[2], material);
  return material;
}

// Text that fits the piece: at most 40 % of its height, and its width over the ID's length.
double id_height(const Rect& b, const std::string& id) {
  return std::max(0.1, std::min(b.h * 0.4, b.w / (0.75 * static_cast<double>(id.size()) + 1)));
}

// What the file draws, for its header's extents: the outline (or the surface), openings, every
// piece, and the caption under it (about 0.6 of its height a character). Blocks draw their plan
// alone, so the surface's width (plan and elevation side by side) is not theirs.
Rect drawn_extents(const Layout& layout, double caption_height, size_t caption_length) {
  double x0 = 0, y0 = -2 * caption_height;
  double x1 = 0.6 * caption_height * static_cast<double>(caption_length), y1 = 0;
  auto add = [&](const Rect& r) {
    x0 = std::min(x0, r.x), y0 = std::min(y0, r.y);
    x1 = std::max(x1, r.right()), y1 = std::max(y1, r.top());
  };
  if (!layout.outline.empty())
    for (const auto& p : layout.outline) add(Rect{p[0], p[1], 0, 0});
  else if (!layout.block_views)
    add(Rect{0, 0, layout.width, layout.height});
  for (const Rect& o : layout.openings) add(o);
  for (const Element& e : layout.elements) add(laid_bounds(e));
  return Rect{x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

void write_layout_dxf(const std::filesystem::path& path, const Layout& layout,
                      bool in_site_drawing) {
  const std::optional<SiteFrame> frame =
      in_site_drawing ? layout.site_frame : std::optional<SiteFrame>{};
  // Layers named for what they hold: a façade's windows are OPENINGS, a planter kept free of
  // paving is one of the ZONES.
  std::vector<DxfLayer> layers{{"OUTLINE", kInk, true}};
  if (layout.openings_given > 0) layers.push_back({"OPENINGS", Rgb{90, 90, 90}, true});
  if (!layout.zones.empty()) layers.push_back({"ZONES", Rgb{68, 81, 92}, true});
  if (layout.planting && layout.planting->any_pit())
    layers.push_back({"TREE_PITS", Rgb{110, 80, 50}, true});
  if (layout.fabrication) layers.push_back({"SHEETS", Rgb{0, 128, 0}, false});
  std::map<std::string, bool> seen;
  for (const Element& e : layout.elements) {
    stop_point();
    const std::string name = layer_of(layout, e);
    if (seen.emplace(name, true).second) layers.push_back({name, piece_colour(layout, e), true});
  }
  layers.push_back({"ID", Rgb{0, 0, 255}, false});
  layers.push_back({"TEXT", kInk, true});
  const Rect surface{0, 0, layout.width, layout.height};
  const double h = std::max(10.0, std::min(layout.width, layout.height) / 100);
  const std::string caption =
      frame ? fmt::format("{} - seed {} - in the coordinates of {}, {}", layout.source.recipe,
                          layout.source.seed, frame->file, frame->unit_name)
            : fmt::format("{} - seed {} - millimetres from the bottom-left corner",
                          layout.source.recipe, layout.source.seed);
  DxfDocument dxf(path, layers, drawn_extents(layout, h, caption.size()), frame);

  if (!layout.outline_contour.empty())
    dxf.contour("OUTLINE", layout.outline_contour);  // its arcs as bulges
  else if (!layout.outline.empty())
    dxf.polygon("OUTLINE", layout.outline);
  else if (!layout.block_views)  // blocks are drawn as views, not a surface
    dxf.rect("OUTLINE", surface);
  for (size_t i = 0; i < layout.openings_given; ++i) dxf.rect("OPENINGS", layout.openings[i]);
  for (const ZoneCount& z : layout.zones) {
    if (!z.contour.empty())
      dxf.contour("ZONES", z.contour);
    else if (!z.polygon.empty())
      dxf.polygon("ZONES", z.polygon);
  }
  for (const Element& e : layout.elements) {
    stop_point();
    const std::string layer = layer_of(layout, e);
    if (const std::optional<Rect> pit = tree_pit(layout, e)) dxf.rect("TREE_PITS", *pit);
    if (e.circle) {
      dxf.circle(layer, e.circle->cx, e.circle->cy, e.circle->d);
      continue;
    }
    const std::vector<Outline> outlines = piece_outlines(e);
    if (!outlines.empty()) {
      for (const Outline& o : outlines)
        for (const Ring& ring : o.rings) dxf.polygon(layer, ring);
      continue;
    }
    dxf.rect(layer, laid_bounds(e));
  }
  // Each fabrication sheet where it lies, by its ID, so that its cutting file can be found on
  // the plan (and, in layout-site.dxf, on the site drawing).
  for (const auto& s : layout.sheets()) {
    dxf.rect("SHEETS", s.area);
    dxf.text("SHEETS", s.area.x + s.area.w / 2, s.area.y + s.area.h / 2,
             std::max(0.1, std::min(s.area.w, s.area.h) / 10), s.id, true);
  }
  for (const Element& e : layout.elements) {
    stop_point();
    const Rect b = label_bounds(e);
    dxf.text("ID", b.x + b.w / 2, b.y + b.h / 2, id_height(b, e.id), e.id, true);
  }
  dxf.text("TEXT", 0, -2 * h, h, caption, false);
  dxf.close();
}

}  // namespace curdle
