#include "site/dxf_groups.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdio>

#include "curdle/text.h"
#include "site/drawing.h"

namespace curdle::site {
namespace {

std::string_view trimmed(std::string_view v) {
  while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
  while (!v.empty() && (v.back() == ' ' || v.back() == '\t' || v.back() == '\r'))
    v.remove_suffix(1);
  return v;
}

// A value as it may be shown in a message: at most 40 characters, control characters as '?'.
std::string shown(std::string_view v) {
  std::string s(v.substr(0, 40));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = '?';
  return v.size() > 40 ? s + "..." : s;
}

}  // namespace

DxfGroups::DxfGroups(std::string_view bytes, std::string file)
    : bytes_(bytes), file_(std::move(file)) {
  if (bytes_.substr(0, 3) == "\xEF\xBB\xBF") bytes_.remove_prefix(3);  // a UTF-8 mark
}

std::string_view DxfGroups::line() {
  const size_t end = std::min(bytes_.find('\n', at_), bytes_.size());
  if (end - at_ > kLongestDxfLine)
    throw InputError(fmt::format(
        "{}: line {} is {} characters long, longer than any DXF's ({}); the file is damaged or "
        "not a DXF: export the drawing as DXF again",
        file_, line_ + 1, end - at_, kLongestDxfLine));
  std::string_view l = bytes_.substr(at_, end - at_);
  at_ = end + 1;
  ++line_;
  return l;
}

bool DxfGroups::next(DxfGroup& group) {
  if (held_) {
    held_ = false;
    group = held_group_;
    return true;
  }
  // Blank lines after the last group (or EOF's) end the file.
  if (bytes_.find_first_not_of(" \t\r\n", at_) == std::string_view::npos) return false;
  const std::string_view code_text = trimmed(line());
  const size_t code_line = line_;
  int code = -1;
  const auto [end, error] =
      std::from_chars(code_text.data(), code_text.data() + code_text.size(), code);
  if (error != std::errc() || end != code_text.data() + code_text.size() || code < 0 || code > 1071)
    throw InputError(fmt::format(
        "{}: line {} should be a group code (a whole number from 0 to 1071) and holds \"{}\"; "
        "the file is damaged or not an ASCII DXF: export the drawing as DXF again",
        file_, code_line, shown(code_text)));
  if (at_ > bytes_.size())
    throw InputError(fmt::format(
        "{}: ends after the group code at line {}, without its value; the file is cut short: "
        "export the drawing as DXF again",
        file_, code_line));
  group.code = code;
  group.value = trimmed(line());
  group.line = line_;
  return true;
}

void DxfGroups::put_back(const DxfGroup& group) {
  held_ = true;
  held_group_ = group;
}

double DxfGroups::real(const DxfGroup& group, std::string_view entity) const {
  double v = 0;
  const char* first = group.value.data();
  const char* last = first + group.value.size();
  if (first != last && *first == '+') ++first;
  const auto [end, error] = std::from_chars(first, last, v);
  if (error != std::errc() || end != last || first == last || !std::isfinite(v))
    throw InputError(fmt::format(
        "{}: line {}: the {} has \"{}\" for group {}, which must be one finite number written "
        "as DXF writes them (e.g. 1.5 or -2.5E+03); the file is damaged: export it again",
        file_, group.line, entity, shown(group.value), group.code));
  return v;
}

double DxfGroups::real_of(const std::vector<DxfGroup>& groups, int code, double fallback,
                          std::string_view entity) const {
  for (const DxfGroup& g : groups)
    if (g.code == code) return real(g, entity);
  return fallback;
}

int64_t DxfGroups::integer_of(const std::vector<DxfGroup>& groups, int code, int64_t fallback,
                              std::string_view entity) const {
  for (const DxfGroup& g : groups)
    if (g.code == code) return integer(g, entity);
  return fallback;
}

int64_t DxfGroups::integer(const DxfGroup& group, std::string_view entity) const {
  int64_t v = 0;
  const char* first = group.value.data();
  const char* last = first + group.value.size();
  if (first != last && *first == '+') ++first;
  const auto [end, error] = std::from_chars(first, last, v);
  if (error != std::errc() || end != last || first == last)
    throw InputError(fmt::format(
        "{}: line {}: the {} has \"{}\" for group {}, which must be one whole number; the file "
        "is damaged: export it again",
        file_, group.line, entity, shown(group.value), group.code));
  return v;
}

// Layer names as the drawing wrote them: UTF-8, or Windows-1252 in older files; `\U+XXXX` is
// the DXF escape for any other character.
std::string decoded_name(std::string_view raw) {
  std::string text;
  if (valid_utf8(raw)) {
    text = raw;
  } else {
    static const char16_t kHigh[32] = {
        0x20AC, 0xFFFD, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
        0x2039, 0x0152, 0xFFFD, 0x017D, 0xFFFD, 0xFFFD, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
        0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0xFFFD, 0x017E, 0x0178};
    for (unsigned char c : raw) append_utf8(text, c < 0x80 ? c : (c < 0xA0 ? kHigh[c - 0x80] : c));
  }
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    unsigned cp = 0;
    if (text.compare(i, 3, "\\U+") == 0 && i + 7 <= text.size() &&
        std::sscanf(text.c_str() + i + 3, "%4x", &cp) == 1 && cp >= 0x20 &&
        (cp < 0xD800 || cp > 0xDFFF)) {
      append_utf8(out, cp);
      i += 6;
      continue;
    }
    out += text[i];
  }
  return shown_name(out);  // a control character in a name never reaches a terminal raw
}

}  // namespace curdle::site
