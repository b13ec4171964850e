// RFC 4180 CSV: a field, quoted when it holds a comma, a quote or a line break.
#pragma once

#include <string>
#include <string_view>

namespace curdle {

// Written first in every CSV file: spreadsheets then read names such as "grès" as UTF-8, and
// strict RFC 4180 readers that expect UTF-8 skip it.
inline constexpr const char* kUtf8Mark = "\xEF\xBB\xBF";

// A text field. One that begins with =, +, -, @, a tab or a carriage return is a formula to
// Excel and LibreOffice: it gets a leading ' (OWASP's rule for CSV injection), shown as text.
// Appended to `out` in place (a schedule writes one for every piece's outline).
inline void append_csv_field(std::string& out, std::string_view text) {
  const bool formula =
      !text.empty() && std::string_view("=+-@\t\r").find(text[0]) != std::string::npos;
  const bool quoted = text.find_first_of(",\"\r\n") != std::string_view::npos;
  if (quoted) out += '"';
  if (formula) out += '\'';
  if (!quoted) {
    out += text;
    return;
  }
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

inline std::string csv_field(const std::string& text) {
  std::string out;
  append_csv_field(out, text);
  return out;
}

}  // namespace curdle
