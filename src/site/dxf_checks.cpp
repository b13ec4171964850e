#include "site/dxf_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>

#include "site/drawing.h"

namespace curdle::site {
namespace {

// What the first bytes say a file is, when it is not an ASCII DXF.
void check_is_ascii_dxf(std::string_view bytes, const std::string& file) {
  if (bytes.size() > kMostDrawingBytes)
    throw InputError(
        fmt::format("{}: is {} MiB; a site drawing may be at most {} MiB (keep only "
                    "the layers of the surface)",
                    file, bytes.size() >> 20, kMostDrawingBytes >> 20));
  if (bytes.substr(0, 18) == "AutoCAD Binary DXF")
    throw InputError(file +
                     ": is a binary DXF; save it as an ASCII DXF (in AutoCAD: SAVEAS, "
                     "DXF, with Options > DXF format ASCII)");
  if (bytes.size() >= 6 && bytes.substr(0, 2) == "AC" && bytes[2] >= '1' && bytes[2] <= '2' &&
      std::isdigit(static_cast<unsigned char>(bytes[3])))
    throw InputError(file +
                     ": is a DWG drawing, which curdle does not read; save it as DXF "
                     "(SAVEAS, DXF, AutoCAD 2000 or later)");
  // An ASCII DXF begins with the group code 0 and SECTION (after an optional 999 comment).
  const size_t first = bytes.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  // Its first line is that group code alone: dxflib spun without end on one long line that
  // began with 0.
  const size_t eol = first == std::string_view::npos ? first : bytes.find('\n', first);
  std::string_view code = eol == std::string_view::npos ? "" : bytes.substr(first, eol - first);
  while (!code.empty() && (code.back() == '\r' || code.back() == ' ' || code.back() == '\t'))
    code.remove_suffix(1);
  const bool looks = first != std::string_view::npos &&
                     bytes.find("SECTION") != std::string_view::npos &&
                     (code == "0" || code == "999");
  if (!looks)
    throw InputError(file +
                     ": is not a DXF drawing (an ASCII DXF begins with the group code 0 "
                     "and SECTION); export the drawing as DXF");
  if (bytes.find('\0') != std::string_view::npos)
    throw InputError(file +
                     ": holds NUL bytes, which an ASCII DXF never does; export it as DXF "
                     "again");
}

// dxflib allocates what an entity's count says before it reads the vertices (an LWPOLYLINE
// declaring 99,999,999 vertices took 3 GB): every count it trusts is checked against the groups
// the file holds first.
// The number a line begins with, as atoi reads it (0 where there is none), held to 64 bits.
int64_t leading_number(std::string_view text) {
  size_t i = 0;
  const bool minus = !text.empty() && text[0] == '-';
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) ++i;
  int64_t n = 0;
  for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i)
    n = n > (INT64_MAX - 9) / 10 ? INT64_MAX : n * 10 + (text[i] - '0');
  return minus ? -n : n;
}

void check_counts(std::string_view bytes, const std::string& file) {
  struct Count {
    std::string_view entity;
    int code;
  };
  static constexpr Count kCounts[] = {
      {"LWPOLYLINE", 90}, {"SPLINE", 72}, {"SPLINE", 73}, {"SPLINE", 74}, {"LEADER", 76},
      {"HATCH", 91},      {"HATCH", 92},  {"HATCH", 93},  {"HATCH", 95},  {"HATCH", 96},
      {"HATCH", 97},      {"HATCH", 98},  {"MLINE", 72},  {"MLINE", 73}};
  const auto groups = static_cast<int64_t>(std::count(bytes.begin(), bytes.end(), '\n') / 2 + 1);
  std::string_view entity;
  size_t at = 0, line = 0;
  auto next_line = [&]() {
    const size_t end = std::min(bytes.find('\n', at), bytes.size());
    std::string_view l = bytes.substr(at, end - at);
    at = end + 1, ++line;
    while (!l.empty() && (l.back() == '\r' || l.back() == ' ' || l.back() == '\t'))
      l.remove_suffix(1);
    while (!l.empty() && (l.front() == ' ' || l.front() == '\t')) l.remove_prefix(1);
    return l;
  };
  while (at < bytes.size()) {
    const std::string_view code_text = next_line();
    if (at > bytes.size()) break;
    const std::string_view value = next_line();
    // As dxflib reads them (atoi): text that is no number is group code 0.
    const auto code = static_cast<int>(leading_number(code_text));
    if (code == 0) {
      entity = value;
      continue;
    }
    for (const Count& c : kCounts) {
      if (c.code != code || c.entity != entity) continue;
      const int64_t n = leading_number(value);
      if (n < 0 || n > groups)
        throw InputError(
            fmt::format("{}: the {} at line {} says it has {} parts, more than the "
                        "file's {} groups hold; the file is damaged: export it as "
                        "DXF again",
                        file, entity, line, value, groups));
    }
  }
}

}  // namespace

void check_dxf_bytes(std::string_view bytes, const std::string& file) {
  check_is_ascii_dxf(bytes, file);
  check_counts(bytes, file);
}

}  // namespace curdle::site
