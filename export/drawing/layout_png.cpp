#include "export/drawing/layout_png.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "curdle/error.h"
#include "curdle/stop.h"
#include "export/drawing/page_buffer.h"
#include "layout/drawing_sheet.h"
#include "layout/ground_colour.h"
#include "layout/piece.h"

namespace curdle {
namespace {

constexpr int64_t kMaxPixels = 16000;  // a side; beyond this the scale is raised

struct Canvas {
  int width, height;
  double px_per_mm;
  double layout_height;
  PageBuffer pixels{0};  // tens of MB for a sheet's layout: on pages of its own
  float* rgb = nullptr;  // in `pixels`, set once to the background
  size_t size = 0;
  // Set while pieces that never overlap are painted: each takes its share of a pixel from
  // the ground under it, so that two pieces meeting inside a pixel leave no light seam (one
  // painted over the other leaves a quarter of the ground showing).
  std::optional<Rgb> ground;

  void blend(float* p, double a, const Rgb& c) const {
    const float g[3] = {ground ? ground->r : p[0], ground ? ground->g : p[1],
                        ground ? ground->b : p[2]};
    p[0] += static_cast<float>(a * (c.r - g[0]));
    p[1] += static_cast<float>(a * (c.g - g[1]));
    p[2] += static_cast<float>(a * (c.b - g[2]));
  }

  // Paints an axis-aligned rectangle (mm, y up) weighting each pixel by the share it covers.
  void fill(const Rect& r, const Rgb& c) {
    const double x0 = r.x * px_per_mm, x1 = r.right() * px_per_mm;
    const double y0 = (layout_height - r.top()) * px_per_mm, y1 = (layout_height - r.y) * px_per_mm;
    const int ix0 = std::max(0, static_cast<int>(std::floor(x0)));
    const int ix1 = std::min(width - 1, static_cast<int>(std::ceil(x1)) - 1);
    const int iy0 = std::max(0, static_cast<int>(std::floor(y0)));
    const int iy1 = std::min(height - 1, static_cast<int>(std::ceil(y1)) - 1);
    for (int y = iy0; y <= iy1; ++y) {
      const double cy = std::min<double>(y + 1, y1) - std::max<double>(y, y0);
      for (int x = ix0; x <= ix1; ++x) {
        const double a = cy * (std::min<double>(x + 1, x1) - std::max<double>(x, x0));
        if (a <= 0) continue;
        blend(&rgb[(static_cast<size_t>(y) * width + x) * 3], a, c);
      }
    }
  }

  // Paints a shape given by an inside test over its bounding box (mm), 4 x 4 samples a pixel.
  template <class Inside>
  void fill_shape(double x0, double y0, double x1, double y1, const Rgb& c, Inside inside) {
    const int ix0 = std::max(0, static_cast<int>(std::floor(x0 * px_per_mm)));
    const int ix1 = std::min(width - 1, static_cast<int>(std::ceil(x1 * px_per_mm)));
    const int iy0 = std::max(0, static_cast<int>(std::floor((layout_height - y1) * px_per_mm)));
    const int iy1 =
        std::min(height - 1, static_cast<int>(std::ceil((layout_height - y0) * px_per_mm)));
    for (int y = iy0; y <= iy1; ++y)
      for (int x = ix0; x <= ix1; ++x) {
        int hits = 0;
        for (int sy = 0; sy < 4; ++sy)
          for (int sx = 0; sx < 4; ++sx)
            hits += inside((x + (sx + 0.5) / 4) / px_per_mm,
                           layout_height - (y + (sy + 0.5) / 4) / px_per_mm);
        if (!hits) continue;
        const double a = hits / 16.0;
        blend(&rgb[(static_cast<size_t>(y) * width + x) * 3], a, c);
      }
  }

  void fill(const Circle& c, const Rgb& colour) {
    const double r = c.d / 2;
    fill_shape(c.cx - r, c.cy - r, c.cx + r, c.cy + r, colour, [&](double x, double y) {
      return (x - c.cx) * (x - c.cx) + (y - c.cy) * (y - c.cy) <= r * r;
    });
  }

  // Even-odd over all rings, so islands stay material: scanlines, 4 x 4 samples a pixel, each
  // sample row crossing every edge once (an outline beyond a curved edge has thousands).
  void fill(const Outline& o, const Rgb& colour) {
    double y0 = 1e300, y1 = -1e300;
    for (const Ring& ring : o.rings)
      for (const auto& v : ring) y0 = std::min(y0, v[1]), y1 = std::max(y1, v[1]);
    const int iy0 = std::max(0, static_cast<int>(std::floor((layout_height - y1) * px_per_mm)));
    const int iy1 =
        std::min(height - 1, static_cast<int>(std::ceil((layout_height - y0) * px_per_mm)));
    std::vector<int> hits(static_cast<size_t>(width));
    std::vector<double> crossings;
    for (int y = iy0; y <= iy1; ++y) {
      std::fill(hits.begin(), hits.end(), 0);
      int first = width, last = -1;
      for (int sy = 0; sy < 4; ++sy) {
        const double at = layout_height - (y + (sy + 0.5) / 4) / px_per_mm;  // mm
        crossings.clear();
        for (const Ring& ring : o.rings)
          for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
            if ((ring[i][1] > at) != (ring[j][1] > at))
              crossings.push_back((ring[j][0] - ring[i][0]) * (at - ring[i][1]) /
                                      (ring[j][1] - ring[i][1]) +
                                  ring[i][0]);
        std::sort(crossings.begin(), crossings.end());
        for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
          // Samples (s + 0.5) / 4 px with crossings[k] <= x < crossings[k + 1].
          const double a = crossings[k] * px_per_mm * 4 - 0.5,
                       b = crossings[k + 1] * px_per_mm * 4 - 0.5;
          const long s0 = std::max(0L, static_cast<long>(std::ceil(a)));
          const long s1 = std::min(4L * width - 1, static_cast<long>(std::ceil(b)) - 1);
          for (long s = s0; s <= s1; ++s) ++hits[static_cast<size_t>(s / 4)];
          if (s0 <= s1)
            first = std::min(first, static_cast<int>(s0 / 4)),
            last = std::max(last, static_cast<int>(s1 / 4));
        }
      }
      for (int x = first; x <= last; ++x) {
        if (!hits[static_cast<size_t>(x)]) continue;
        const double a = hits[static_cast<size_t>(x)] / 16.0;
        blend(&rgb[(static_cast<size_t>(y) * width + x) * 3], a, colour);
      }
    }
  }
};

}  // namespace

uint64_t layout_png_pixels(const LayoutSpec& spec, const Box& view) {
  const Layout outline = layout_extent(spec, view);
  const double ppm = spec.drawing.dpi / 25.4 / drawing_scale(outline);
  return static_cast<uint64_t>(std::ceil(outline.width * ppm) * std::ceil(outline.height * ppm));
}

PreviewImage render_layout(const Layout& layout) {
  Canvas canvas;
  canvas.px_per_mm = layout.drawing.dpi / 25.4 / drawing_scale(layout);
  canvas.layout_height = layout.height;
  canvas.width = std::max(1, static_cast<int>(std::ceil(layout.width * canvas.px_per_mm)));
  canvas.height = std::max(1, static_cast<int>(std::ceil(layout.height * canvas.px_per_mm)));
  if (canvas.width > kMaxPixels || canvas.height > kMaxPixels)
    throw InputError("layout.png would be " + std::to_string(canvas.width) + " x " +
                     std::to_string(canvas.height) + " pixels, above " +
                     std::to_string(kMaxPixels) +
                     " a side; use a larger layout.scale or lower layout.dpi");
  const Rgb background = ground_colour(layout);
  canvas.size = static_cast<size_t>(canvas.width) * canvas.height * 3;
  canvas.pixels = PageBuffer(canvas.size * sizeof(float));
  canvas.rgb = canvas.pixels.as<float>();
  for (size_t i = 0; i < canvas.size; i += 3)
    canvas.rgb[i] = background.r, canvas.rgb[i + 1] = background.g,
    canvas.rgb[i + 2] = background.b;
  for (const Rect& o : layout.openings) canvas.fill(o, Rgb{223, 234, 242});
  for (const Rect& o : layout.outside) canvas.fill(o, Rgb{255, 255, 255});  // not the surface
  for (const Outline& o : layout.cut_away) canvas.fill(o, Rgb{255, 255, 255});
  if (layout.block_views)
    for (const BlockViews::Cell& v : layout.block_views->cells)
      canvas.fill(v.rect, layout.legend[v.value].colour);
  for (const Element& e : layout.elements) {
    stop_point();
    if (layout.block_views) break;  // blocks are drawn as their views
    const LegendEntry& entry = layout.legend[e.value];
    // Pieces tile the surface; a park's standing objects are painted over its ground.
    canvas.ground = e.stands ? std::nullopt : std::optional<Rgb>(background);
    if (!e.type.empty()) {  // park: each element in its own colour
      if (e.circle) canvas.fill(*e.circle, e.colour);
      if (e.outline) canvas.fill(*e.outline, e.colour);
      for (const Rect& r : e.shape) canvas.fill(r, e.colour);
      continue;
    }
    if (e.circle) {
      canvas.fill(*e.circle, entry.colour);
      continue;
    }
    if (e.outline) {
      canvas.fill(*e.outline, entry.colour);
      continue;
    }
    // keep: each curd present keeps its own stripe of the element.
    for (const ColouredRect& stripe : keep_stripes(layout, e))
      canvas.fill(stripe.rect, stripe.colour);
  }
  PreviewImage image;
  image.width = canvas.width;
  image.height = canvas.height;
  image.rgb.resize(canvas.size);
  for (size_t i = 0; i < canvas.size; ++i)  // to the nearest, as lround, without its call
    image.rgb[i] = static_cast<uint8_t>(std::clamp(canvas.rgb[i], 0.f, 255.f) + 0.5f);
  return image;
}

}  // namespace curdle
