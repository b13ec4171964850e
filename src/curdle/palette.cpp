#include "curdle/palette.h"

#include <array>
#include <charconv>
#include <cstdint>

#include "curdle/markov.h"

namespace curdle {

namespace {

constexpr std::array<Rgb, 8> kDefaults{{{192, 57, 43},   // brick red
                                        {46, 94, 170},   // blue
                                        {224, 165, 38},  // ochre
                                        {58, 138, 79},   // green
                                        {40, 40, 40},    // charcoal
                                        {142, 68, 173},  // violet
                                        {22, 160, 160},  // teal
                                        {160, 100, 60}}};

}  // namespace

Rgb curd_colour(const std::vector<CurdSpec>& curds, size_t curd) {
  if (curds[curd].colour) return *curds[curd].colour;
  return kDefaults[curd % kDefaults.size()];
}

Rgb state_colour(const std::vector<CurdSpec>& curds, const CurdGroup& group, uint32_t state) {
  if (!group.chain) return curd_colour(curds, group.first);
  const auto& own = group.chain->colours;
  if (state >= 1 && state <= own.size() && own[state - 1]) return *own[state - 1];
  return kDefaults[(group.first + state - 1) % kDefaults.size()];
}

std::vector<Rgb> value_parts(const std::vector<CurdSpec>& curds, uint32_t value) {
  std::vector<Rgb> parts;
  for (const CurdGroup& g : curd_groups(curds))
    if (const uint32_t state = g.state(value)) parts.push_back(state_colour(curds, g, state));
  return parts;
}

std::vector<Rgb> value_colours(const std::vector<CurdSpec>& curds) {
  std::vector<Rgb> colours(size_t{1} << curds.size(), kEmptyColour);
  for (size_t v = 1; v < colours.size(); ++v) {
    const std::vector<Rgb> parts = value_parts(curds, static_cast<uint32_t>(v));
    if (parts.empty()) continue;
    unsigned r = 0, g = 0, b = 0;
    for (const Rgb& col : parts) r += col.r, g += col.g, b += col.b;
    const auto n = static_cast<unsigned>(parts.size());
    colours[v] =
        Rgb{static_cast<uint8_t>(r / n), static_cast<uint8_t>(g / n), static_cast<uint8_t>(b / n)};
  }
  return colours;
}

}  // namespace curdle

namespace curdle {

// By hand: a writer asks this for every piece, and snprintf was 2.5 % of a building's run.
std::string hex_colour(const Rgb& c) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string text(7, '#');
  const uint8_t channels[3] = {c.r, c.g, c.b};
  for (int i = 0; i < 3; ++i) {
    text[1 + 2 * i] = kDigits[channels[i] >> 4];
    text[2 + 2 * i] = kDigits[channels[i] & 0xf];
  }
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
