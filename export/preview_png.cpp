#include "export/preview_png.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "export/atomic_file.h"

namespace curdle {
namespace {

constexpr int64_t kTargetPixels = 1024;  // the long side of a panel, roughly
constexpr int64_t kMaxPanelPixels = 4096;
constexpr int kGap = 6;
constexpr Rgb kBackground{255, 255, 255};

}  // namespace

PreviewImage render_preview(const Design& design, const CurdField& field, const Box& view) {
  const int E = design.lattice.dimension;
  // Panels: E=2 one, E=3 one per z, E=1 lines of the strip.
  int64_t panel_w = view.size[0], panel_h = E == 1 ? 1 : view.size[1];
  int64_t panels = E == 3 ? view.size[2] : 1;
  if (E == 1 && panel_w > kTargetPixels) {
    panel_w = kTargetPixels * std::max<int64_t>(1, (view.size[0] + kTargetPixels * 256 - 1) /
                                                       (kTargetPixels * 256));
    panels = (view.size[0] + panel_w - 1) / panel_w;
  }
  const int64_t columns = E == 3 ? static_cast<int64_t>(std::ceil(std::sqrt(double(panels)))) : 1;
  const int64_t rows = (panels + columns - 1) / columns;
  // Cells per pixel (down) or pixels per cell (up), so that the whole sheet stays readable.
  const int64_t longest = std::max(panel_w * columns, E == 1 ? panel_w : panel_h * rows);
  const int64_t per_pixel = std::max<int64_t>(1, (longest + kMaxPanelPixels - 1) / kMaxPanelPixels);
  const int64_t scale = per_pixel > 1 ? 1 : std::clamp<int64_t>(kTargetPixels / longest, 1, 32);
  const int64_t pw = (panel_w + per_pixel - 1) / per_pixel * scale;
  const int64_t strip = E == 1 ? std::max<int64_t>(scale, 48) : 0;
  const int64_t ph = E == 1 ? strip : (panel_h + per_pixel - 1) / per_pixel * scale;

  PreviewImage image;
  image.width = static_cast<int>(columns * pw + (columns - 1) * kGap);
  image.height = static_cast<int>(rows * ph + (rows - 1) * kGap);
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  std::vector<uint32_t> sum(pixels * 4, 0);  // r, g, b, cells

  const std::vector<Rgb> colours = value_colours(design.curds);
  auto add = [&](int64_t px, int64_t py, const Rgb& c) {
    uint32_t* s = &sum[(static_cast<size_t>(py) * image.width + px) * 4];
    s[0] += c.r, s[1] += c.g, s[2] += c.b, s[3] += 1;
  };
  scan_rows(field, view, [&](int64_t y, int64_t z, std::span<const uint16_t> row) {
    for (size_t i = 0; i < row.size(); ++i) {
      int64_t u = static_cast<int64_t>(i), v = y - view.origin[1], panel = z - view.origin[2];
      if (E == 1) panel = u / panel_w, u %= panel_w, v = 0;
      const int64_t ox = (panel % columns) * (pw + kGap), oy = (panel / columns) * (ph + kGap);
      const Rgb& c = colours[row[i]];
      if (E == 1) {
        const int64_t x0 = ox + u / per_pixel * scale;
        for (int64_t dx = 0; dx < scale; ++dx)
          for (int64_t dy = 0; dy < strip; ++dy) add(x0 + dx, oy + dy, c);
        continue;
      }
      const int64_t x0 = ox + u / per_pixel * scale;
      const int64_t y0 = oy + (ph - scale) - v / per_pixel * scale;  // y up
      for (int64_t dy = 0; dy < scale; ++dy)
        for (int64_t dx = 0; dx < scale; ++dx) add(x0 + dx, y0 + dy, c);
    }
  });
  image.rgb.resize(pixels * 3);
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

void write_png(const std::filesystem::path& target, const PreviewImage& image) {
  StagedFile staged(target);
  auto out = OIIO::ImageOutput::create("png");
  if (!out) throw std::runtime_error("OpenImageIO has no PNG writer: " + OIIO::geterror());
  const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  if (!out->open(staged.temporary().string(), spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, image.rgb.data()) || !out->close())
    throw InputError("cannot write " + target.string() + ": " + out->geterror());
  staged.commit();
}

}  // namespace curdle
