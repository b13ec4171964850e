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
inline std::string csv_field(const std::string& text) {
  const bool formula =
      !text.empty() && std::string_view("=+-@\t\r").find(text[0]) != std::string::npos;
  const std::string s = formula ? "'" + text : text;
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  q += '"';
  return q;
}

}  // namespace curdle
