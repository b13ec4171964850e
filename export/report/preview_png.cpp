#include "export/report/preview_png.h"

#include <algorithm>
#include <cmath>

#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"

namespace curdle {
namespace {

constexpr int64_t kTargetPixels = 1024;  // the long side of a panel, roughly
constexpr int64_t kMaxPanelPixels = 4096;
constexpr int kGap = 6;
constexpr Rgb kBackground{255, 255, 255};

// Where panels and cells go in the image.
struct SheetLayout {
  int64_t panel_w, panel_h, panels, columns, rows;
  int64_t per_pixel;  // cells per pixel when averaging down
  int64_t scale;      // pixels per cell when scaling up
  int64_t pw, ph, strip;
  int width, height;
};

SheetLayout lay_out(const Design& design, const Box& view) {
  const int E = design.lattice.dimension;
  SheetLayout s{};
  // Panels: E=2 one, E=3 one per z, E=1 lines of the strip.
  s.panel_w = view.size[0];
  s.panel_h = E == 1 ? 1 : view.size[1];
  s.panels = E == 3 ? view.size[2] : 1;
  if (E == 1 && s.panel_w > kTargetPixels) {
    s.panel_w = kTargetPixels * std::max<int64_t>(1, (view.size[0] + kTargetPixels * 256 - 1) /
                                                         (kTargetPixels * 256));
    s.panels = (view.size[0] + s.panel_w - 1) / s.panel_w;
  }
  s.columns = E == 3 ? static_cast<int64_t>(std::ceil(std::sqrt(double(s.panels)))) : 1;
  s.rows = (s.panels + s.columns - 1) / s.columns;
  // Cells per pixel (down) or pixels per cell (up), so that the whole sheet stays readable.
  const int64_t longest = std::max(s.panel_w * s.columns, E == 1 ? s.panel_w : s.panel_h * s.rows);
  s.per_pixel = std::max<int64_t>(1, (longest + kMaxPanelPixels - 1) / kMaxPanelPixels);
  s.scale = s.per_pixel > 1 ? 1 : std::clamp<int64_t>(kTargetPixels / longest, 1, 32);
  s.pw = (s.panel_w + s.per_pixel - 1) / s.per_pixel * s.scale;
  s.strip = E == 1 ? std::max<int64_t>(s.scale, 48) : 0;
  s.ph = E == 1 ? s.strip : (s.panel_h + s.per_pixel - 1) / s.per_pixel * s.scale;
  s.width = static_cast<int>(s.columns * s.pw + (s.columns - 1) * kGap);
  s.height = static_cast<int>(s.rows * s.ph + (s.rows - 1) * kGap);
  return s;
}

}  // namespace

uint64_t preview_memory(const Design& design, const Box& view) {
  const SheetLayout s = lay_out(design, view);
  return static_cast<uint64_t>(s.width) * s.height * (4 * sizeof(uint32_t) + 3);
}

PreviewImage render_preview(const Design& design, const CurdField& field, const Box& view,
                            const std::function<void(double)>& progress) {
  const int E = design.lattice.dimension;
  const SheetLayout sheet = lay_out(design, view);
  const int64_t panel_w = sheet.panel_w, columns = sheet.columns, per_pixel = sheet.per_pixel,
                scale = sheet.scale, pw = sheet.pw, ph = sheet.ph, strip = sheet.strip;
  PreviewImage image;
  image.width = sheet.width;
  image.height = sheet.height;
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  const std::vector<Rgb> colours = value_colours(design.curds);
  // Every pixel of each cell's block, in scan order: `emit(px, py, colour)`.
  auto each_pixel = [&](auto&& emit) {
    scan_rows(
        field, view,
        [&](int64_t y, int64_t z, std::span<const uint16_t> row) {
          for (size_t i = 0; i < row.size(); ++i) {
            int64_t u = static_cast<int64_t>(i), v = y - view.origin[1], panel = z - view.origin[2];
            if (E == 1) panel = u / panel_w, u %= panel_w, v = 0;
            const int64_t ox = (panel % columns) * (pw + kGap),
                          oy = (panel / columns) * (ph + kGap);
            const Rgb& c = colours[row[i]];
            const int64_t x0 = ox + u / per_pixel * scale;
            if (E == 1) {
              for (int64_t dx = 0; dx < scale; ++dx)
                for (int64_t dy = 0; dy < strip; ++dy) emit(x0 + dx, oy + dy, c);
              continue;
            }
            const int64_t y0 = oy + (ph - scale) - v / per_pixel * scale;  // y up
            for (int64_t dy = 0; dy < scale; ++dy)
              for (int64_t dx = 0; dx < scale; ++dx) emit(x0 + dx, y0 + dy, c);
          }
        },
        progress);
  };
  image.rgb.resize(pixels * 3);
  if (per_pixel == 1) {
    // A cell to a block of pixels: each pixel shows one cell, painted as it comes (a 64 x 64
    // field spent half its time zero-filling and averaging a 16 MB sum it did not need).
    for (size_t p = 0; p < pixels; ++p)
      image.rgb[p * 3] = kBackground.r, image.rgb[p * 3 + 1] = kBackground.g,
                    image.rgb[p * 3 + 2] = kBackground.b;
    each_pixel([&](int64_t px, int64_t py, const Rgb& c) {
      uint8_t* out = &image.rgb[(static_cast<size_t>(py) * image.width + px) * 3];
      out[0] = c.r, out[1] = c.g, out[2] = c.b;
    });
    return image;
  }
  std::vector<uint32_t> sum(pixels * 4, 0);  // r, g, b, cells: many cells to a pixel
  each_pixel([&](int64_t px, int64_t py, const Rgb& c) {
    uint32_t* s = &sum[(static_cast<size_t>(py) * image.width + px) * 4];
    s[0] += c.r, s[1] += c.g, s[2] += c.b, s[3] += 1;
  });
  for (size_t p = 0; p < pixels; ++p) {
    const uint32_t* s = &sum[p * 4];
    const Rgb c = s[3] ? Rgb{static_cast<uint8_t>((s[0] + s[3] / 2) / s[3]),
                             static_cast<uint8_t>((s[1] + s[3] / 2) / s[3]),
                             static_cast<uint8_t>((s[2] + s[3] / 2) / s[3])}
                       : kBackground;
    image.rgb[p * 3] = c.r, image.rgb[p * 3 + 1] = c.g, image.rgb[p * 3 + 2] = c.b;
  }
  return image;
}

}  // namespace curdle
