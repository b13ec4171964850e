// Numbers in the JSON files curdle writes: rounded to a few decimals (plenty for a report, and
// diffable), null where there is no finite value.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>

namespace curdle {

inline nlohmann::ordered_json rounded(double x, int digits = 4) {
  if (!std::isfinite(x)) return nullptr;
  const double scale = std::pow(10.0, digits);
  return std::round(x * scale) / scale;
}

inline nlohmann::ordered_json rounded(const std::optional<double>& x, int digits = 4) {
  return x ? rounded(*x, digits) : nlohmann::ordered_json(nullptr);
}

// A probability, which may be as small as 1e-300 (an extinction, a share deep in a chain): to
// 12 significant digits, never rounded to 0 by a count of decimals.
inline nlohmann::ordered_json probability_json(double x) {
  if (!std::isfinite(x)) return nullptr;
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", x);
  return std::strtod(text, nullptr);
}

}  // namespace curdle
