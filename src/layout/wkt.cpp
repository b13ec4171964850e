#include "layout/wkt.h"

#include <array>
#include <charconv>
#include <cmath>

namespace curdle {

std::string mm_text(double v) {
  const double rounded = std::round(v * 1000) / 1000;
  std::array<char, 400> buffer{};  // to_chars: exact, and without fmt's slow path
  const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(),
                                 rounded == 0 ? 0.0 : rounded,  // no "-0"
                                 std::chars_format::fixed, 3);
  std::string s(buffer.data(), end.ptr);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

namespace {

std::string polygon_text(const Outline& o) {
  std::string s = "(";
  for (size_t r = 0; r < o.rings.size(); ++r) {
    const Ring& ring = o.rings[r];
    if (ring.empty()) continue;
    s += r ? ", (" : "(";
    for (size_t i = 0; i <= ring.size(); ++i) {
      const auto& v = ring[i % ring.size()];
      s += (i ? ", " : "") + mm_text(v[0]) + " " + mm_text(v[1]);
    }
    s += ")";
  }
  return s + ")";
}

}  // namespace

std::string outlines_wkt(const std::vector<Outline>& outlines) {
  if (outlines.empty()) return "";
  if (outlines.size() == 1) return "POLYGON " + polygon_text(outlines[0]);
  std::string s = "MULTIPOLYGON (";
  for (size_t i = 0; i < outlines.size(); ++i) s += (i ? ", " : "") + polygon_text(outlines[i]);
  return s + ")";
}

}  // namespace curdle
