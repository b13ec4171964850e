#include "layout/wkt.h"

#include <array>
#include <charconv>
#include <cmath>

#include "curdle/fixed_text.h"

namespace curdle {

std::string mm_text(double v) {
  std::string s;
  append_mm_text(s, v);
  return s;
}

void append_mm_text(std::string& out, double v) {
  const double rounded = std::round(v * 1000) / 1000;
  std::array<char, 400> buffer;  // to_chars_fixed: exact, and without fmt's slow path
  const char* first = buffer.data();
  const char* end = to_chars_fixed(buffer.data(), buffer.data() + buffer.size(),
                                   rounded == 0 ? 0.0 : rounded, 3)  // no "-0"
                        .ptr;
  while (end[-1] == '0') --end;
  if (end[-1] == '.') --end;
  out.append(first, end);
}

namespace {

// Written in place: a schedule has a polygon for every piece, and strings made for each number
// were most of schedule.csv's time.
void append_polygon(std::string& s, const Outline& o) {
  s += '(';
  for (size_t r = 0; r < o.rings.size(); ++r) {
    const Ring& ring = o.rings[r];
    if (ring.empty()) continue;
    s += r ? ", (" : "(";
    for (size_t i = 0; i <= ring.size(); ++i) {
      const auto& v = ring[i % ring.size()];
      if (i) s += ", ";
      append_mm_text(s, v[0]);
      s += ' ';
      append_mm_text(s, v[1]);
    }
    s += ')';
  }
  s += ')';
}

}  // namespace

std::string outlines_wkt(const std::vector<Outline>& outlines) {
  std::string s;
  append_outlines_wkt(s, outlines);
  return s;
}

void append_outlines_wkt(std::string& out, const std::vector<Outline>& outlines) {
  if (outlines.empty()) return;
  if (outlines.size() == 1) {
    out += "POLYGON ";
    append_polygon(out, outlines[0]);
    return;
  }
  out += "MULTIPOLYGON (";
  for (size_t i = 0; i < outlines.size(); ++i) {
    if (i) out += ", ";
    append_polygon(out, outlines[i]);
  }
  out += ')';
}

}  // namespace curdle
