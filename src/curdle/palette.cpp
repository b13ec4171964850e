#include "curdle/palette.h"

#include <array>
#include <charconv>
#include <cstdio>

namespace curdle {

Rgb curd_colour(const std::vector<CurdSpec>& curds, size_t curd) {
  static constexpr std::array<Rgb, 8> defaults{{{192, 57, 43},   // brick red
                                                {46, 94, 170},   // blue
                                                {224, 165, 38},  // ochre
                                                {58, 138, 79},   // green
                                                {40, 40, 40},    // charcoal
                                                {142, 68, 173},  // violet
                                                {22, 160, 160},  // teal
                                                {160, 100, 60}}};
  if (curds[curd].colour) return *curds[curd].colour;
  return defaults[curd % defaults.size()];
}

std::vector<Rgb> value_colours(const std::vector<CurdSpec>& curds) {
  std::vector<Rgb> colours(size_t{1} << curds.size(), kEmptyColour);
  for (size_t v = 1; v < colours.size(); ++v) {
    unsigned r = 0, g = 0, b = 0, n = 0;
    for (size_t c = 0; c < curds.size(); ++c) {
      if (!(v >> c & 1)) continue;
      const Rgb col = curd_colour(curds, c);
      r += col.r, g += col.g, b += col.b, ++n;
    }
    colours[v] =
        Rgb{static_cast<uint8_t>(r / n), static_cast<uint8_t>(g / n), static_cast<uint8_t>(b / n)};
  }
  return colours;
}

}  // namespace curdle

namespace curdle {

std::string hex_colour(const Rgb& c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

std::optional<Rgb> parse_hex_colour(std::string_view s) {
  if (s.size() != 7 || s[0] != '#') return std::nullopt;
  unsigned v = 0;
  auto [p, ec] = std::from_chars(s.data() + 1, s.data() + 7, v, 16);
  if (ec != std::errc() || p != s.data() + 7) return std::nullopt;
  return Rgb{static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
}

}  // namespace curdle
