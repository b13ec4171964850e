#include "export/report/measure_files.h"

#include <algorithm>
#include <cmath>

#include "curdle/palette.h"
#include "export/report/json_number.h"

namespace curdle {
namespace {

using json = nlohmann::ordered_json;

constexpr std::array<std::array<uint8_t, 3>, 8> kSeries = {{{214, 39, 40},
                                                            {31, 119, 180},
                                                            {44, 160, 44},
                                                            {148, 103, 189},
                                                            {255, 127, 14},
                                                            {140, 86, 75},
                                                            {227, 119, 194},
                                                            {23, 190, 207}}};

// Points are fitted series in order of value: the colour goes with the series, not the value.
std::vector<const ValueMeasure*> fitted(const Measurement& m) {
  std::vector<const ValueMeasure*> out;
  for (const ValueMeasure& v : m.values)
    if (v.fit) out.push_back(&v);
  return out;
}

struct Plot {
  int width = 900, height = 640, left = 70, right = 30, top = 30, bottom = 60;
  std::vector<uint8_t> rgb;
  Plot() : rgb(static_cast<size_t>(width * height * 3), 255) {}
  void dot(double x, double y, const std::array<uint8_t, 3>& c, double r) {
    for (int py = static_cast<int>(y - r - 1); py <= static_cast<int>(y + r + 1); ++py)
      for (int px = static_cast<int>(x - r - 1); px <= static_cast<int>(x + r + 1); ++px)
        if (px >= 0 && py >= 0 && px < width && py < height &&
            (px + 0.5 - x) * (px + 0.5 - x) + (py + 0.5 - y) * (py + 0.5 - y) <= r * r)
          std::copy(c.begin(), c.end(), rgb.begin() + (static_cast<size_t>(py) * width + px) * 3);
  }
  void line(double x0, double y0, double x1, double y1, const std::array<uint8_t, 3>& c, double r) {
    const int steps = 2 * static_cast<int>(std::hypot(x1 - x0, y1 - y0)) + 1;
    for (int i = 0; i <= steps; ++i)
      dot(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps, c, std::max(r, 0.75));
  }
  // Digits in a 3 x 5 pixel font, `scale` pixels a font pixel, centred on (x, y).
  void number(uint64_t n, double x, double y, int scale) {
    static const char* const glyphs[10] = {"111101101101111", "010110010010111", "111001111100111",
                                           "111001111001111", "101101111001001", "111100111001111",
                                           "111100111101111", "111001001001001", "111101111101111",
                                           "111101111001111"};
    const std::string text = std::to_string(n);
    const int advance = 4 * scale;
    const int x0 = static_cast<int>(x) - static_cast<int>(text.size()) * advance / 2;
    const int y0 = static_cast<int>(y) - 5 * scale / 2;
    for (size_t i = 0; i < text.size(); ++i)
      for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 3; ++c)
          if (glyphs[text[i] - '0'][r * 3 + c] == '1')
            for (int dy = 0; dy < scale; ++dy)
              for (int dx = 0; dx < scale; ++dx) {
                const int px = x0 + static_cast<int>(i) * advance + c * scale + dx;
                const int py = y0 + r * scale + dy;
                if (px >= 0 && py >= 0 && px < width && py < height)
                  std::fill_n(rgb.begin() + (static_cast<size_t>(py) * width + px) * 3, 3, 40);
              }
  }
};

}  // namespace

std::string level_colour(double luminance) {
  const auto g = static_cast<uint8_t>(std::lround(std::clamp(luminance, 0.0, 1.0) * 255));
  return hex_colour(Rgb{g, g, g});
}

std::string series_colour(size_t n) {
  const auto& c = kSeries[n % kSeries.size()];
  return hex_colour(Rgb{c[0], c[1], c[2]});
}

json measure_to_json(const MeasuredPicture& p) {
  const Measurement& m = p.measurement;
  json j;
  j["source"] = p.source;
  j["size"] = {m.width, m.height};
  j["base"] = m.base;
  j["lacunarity_box"] = m.lacunarity_box;
  json values = json::array();
  size_t series = 0;
  for (const ValueMeasure& v : m.values) {
    json row = {{"value", v.value},
                {"colour", level_colour(p.levels.at(v.value))},
                {"count", v.count},
                {"share", rounded(v.share, 6)},
                {"lacunarity", rounded(v.lacunarity)}};
    if (v.most_common) row["ground"] = true;
    if (v.fit) {
      row["box_dimension"] = {{"fit", rounded(v.fit->slope, 4)},
                              {"r2", rounded(v.fit->r2, 4)},
                              {"sizes", v.sizes},
                              {"counts", v.counts}};
      row["plot_colour"] = series_colour(series++);
    }
    values.push_back(row);
  }
  j["values"] = values;
  return j;
}

PreviewImage plot_box_counts(const MeasuredPicture& p) {
  Plot plot;
  const auto series = fitted(p.measurement);
  // Axes: x = log_b(1/s) from -levels to 0 (largest boxes right), y = log_b N.
  double xmax = 1, ymax = 1;
  for (const ValueMeasure* v : series) {
    xmax = std::max(xmax, static_cast<double>(v->sizes.size() - 1));
    for (uint64_t n : v->counts)
      ymax = std::max(ymax, std::log(static_cast<double>(std::max<uint64_t>(n, 1))) /
                                std::log(static_cast<double>(p.measurement.base)));
  }
  ymax = std::ceil(ymax);
  const double w = plot.width - plot.left - plot.right, h = plot.height - plot.top - plot.bottom;
  auto px = [&](double x) { return plot.left + w * x / xmax; };
  auto py = [&](double y) { return plot.top + h * (1 - y / ymax); };
  const std::array<uint8_t, 3> grid{225, 225, 225}, axis{60, 60, 60};
  for (int i = 0; i <= static_cast<int>(xmax); ++i)
    plot.line(px(i), py(0), px(i), py(ymax), grid, 0.5);
  for (int i = 0; i <= static_cast<int>(ymax); ++i)
    plot.line(px(0), py(i), px(xmax), py(i), grid, 0.5);
  plot.line(px(0), py(0), px(xmax), py(0), axis, 1);
  plot.line(px(0), py(0), px(0), py(ymax), axis, 1);
  // Ticks: the box side under each level (largest at the left), the count N = b^i up the side.
  const auto base = static_cast<uint64_t>(p.measurement.base);
  uint64_t side = 1;
  for (int i = static_cast<int>(xmax); i >= 0; --i, side *= base)
    plot.number(side, px(i), py(0) + 22, 2);
  uint64_t count = 1;
  for (int i = 0; i <= static_cast<int>(ymax) && count < (uint64_t{1} << 50); ++i, count *= base)
    if (ymax <= 12 || i % 2 == 0) plot.number(count, plot.left / 2.0, py(i), 2);
  const double log_b = std::log(static_cast<double>(p.measurement.base));
  for (size_t s = 0; s < series.size(); ++s) {
    const ValueMeasure& v = *series[s];
    const auto& colour = kSeries[s % kSeries.size()];
    // Level j from the largest box: x = j; the fit's slope is per level.
    const size_t levels = v.sizes.size();
    double sx = 0, sy = 0;
    int n = 0;
    for (size_t i = 0; i < levels; ++i) {
      if (!v.counts[i]) continue;
      const double x = static_cast<double>(levels - 1 - i);
      const double y = std::log(static_cast<double>(v.counts[i])) / log_b;
      plot.dot(px(x), py(y), colour, 5);
      sx += x, sy += y, ++n;
    }
    if (n < 2) continue;
    const double slope = v.fit->slope, at = sy / n - slope * sx / n;  // through the centroid
    plot.line(px(0), py(at), px(xmax), py(at + slope * xmax), colour, 1.2);
  }
  PreviewImage image;
  image.width = plot.width, image.height = plot.height;
  image.rgb = std::move(plot.rgb);
  return image;
}

}  // namespace curdle
