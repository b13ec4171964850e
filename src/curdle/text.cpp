#include "curdle/text.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstdio>

namespace curdle {
namespace {

// Length of the well-formed UTF-8 sequence at text[i], or 0 (RFC 3629, table 3-7 of Unicode).
size_t sequence_length(std::string_view text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<uint8_t>(text[k]); };
  const uint8_t b0 = byte(i);
  if (b0 < 0x80) return 1;
  size_t n = 0;
  uint8_t lo = 0x80, hi = 0xBF;
  if (b0 >= 0xC2 && b0 <= 0xDF)
    n = 2;
  else if (b0 == 0xE0)
    n = 3, lo = 0xA0;
  else if (b0 >= 0xE1 && b0 <= 0xEC)
    n = 3;
  else if (b0 == 0xED)
    n = 3, hi = 0x9F;  // no surrogates
  else if (b0 >= 0xEE && b0 <= 0xEF)
    n = 3;
  else if (b0 == 0xF0)
    n = 4, lo = 0x90;
  else if (b0 >= 0xF1 && b0 <= 0xF3)
    n = 4;
  else if (b0 == 0xF4)
    n = 4, hi = 0x8F;  // at most U+10FFFF
  else
    return 0;
  if (i + n > text.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

// The code point of the well-formed sequence of `n` bytes at text[i].
uint32_t code_point(std::string_view text, size_t i, size_t n) {
  if (n == 1) return static_cast<uint8_t>(text[i]);
  uint32_t code = static_cast<uint8_t>(text[i]) & (0x7F >> n);
  for (size_t k = 1; k < n; ++k) code = code << 6 | (static_cast<uint8_t>(text[i + k]) & 0x3F);
  return code;
}

// Unicode's non-characters: U+FDD0..U+FDEF and the last two of every plane (XML forbids
// U+FFFE and U+FFFF).
bool is_noncharacter(uint32_t c) { return (c >= 0xFDD0 && c <= 0xFDEF) || (c & 0xFFFE) == 0xFFFE; }

// "U+202E".
std::string u_plus(uint32_t c) {
  char text[16];
  std::snprintf(text, sizeof text, "U+%04X", c);
  return text;
}

bool is_control(uint8_t c) {
  return (c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F;
}

}  // namespace

bool valid_utf8(std::string_view text) {
  for (size_t i = 0; i < text.size();) {
    const size_t n = sequence_length(text, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

bool has_control_characters(std::string_view text) {
  for (char c : text)
    if (is_control(static_cast<uint8_t>(c))) return true;
  return false;
}

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const size_t n = sequence_length(text, i);
    if (n == 0) {  // not UTF-8: dropped
      ++i;
      continue;
    }
    if (n > 1) {
      if (!is_noncharacter(code_point(text, i, n))) out.append(text.substr(i, n));
      i += n;
      continue;
    }
    const char c = text[i++];
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        if (!is_control(static_cast<uint8_t>(c))) out += c;
    }
  }
  return out;
}

std::string unsafe_text(std::string_view text) {
  if (!valid_utf8(text)) return "bytes that are not UTF-8";
  for (size_t i = 0; i < text.size();) {
    const size_t n = sequence_length(text, i);
    const uint32_t c = code_point(text, i, n);
    i += n;
    if (n == 1 && is_control(static_cast<uint8_t>(c))) return "a control character";
    if (n == 1 && (c == '\n' || c == '\r' || c == '\t')) return "a line break or tab";
    if ((c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069) || c == 0x200E ||
        c == 0x200F || c == 0x061C)
      return "a bidirectional control (" + u_plus(c) + ") that reorders what is shown";
    if ((c >= 0x200B && c <= 0x200D) || c == 0x2060 || c == 0xFEFF)
      return "an invisible character (" + u_plus(c) + ")";
    if (is_noncharacter(c)) return "a non-character (" + u_plus(c) + ")";
  }
  return {};
}

std::string shown_name(std::string_view text) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const size_t start = i;
    const uint32_t c = next_code_point(text, i);
    const bool hidden = c < 0x20 || c == 0x7F || (c >= 0x80 && c <= 0x9F) ||
                        (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069) ||
                        (c >= 0x200B && c <= 0x200F) || c == 0x061C || c == 0x2060 || c == 0xFEFF;
    if (c < 0x80 && hidden)
      out += fmt::format("\\x{:02X}", c);
    else if (hidden)
      out += fmt::format("\\u{:04X}", c);
    else if (c == 0xFFFD && i - start == 1)
      out += "\xEF\xBF\xBD";  // a byte that is not UTF-8: U+FFFD
    else
      out.append(text, start, i - start);
  }
  return out;
}

uint32_t next_code_point(std::string_view text, size_t& i) {
  const size_t n = sequence_length(text, i);
  if (n == 0) {
    ++i;
    return 0xFFFD;
  }
  const uint32_t c = code_point(text, i, n);
  i += n;
  return c;
}

void append_utf8(std::string& out, uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

}  // namespace curdle
