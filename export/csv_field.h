// RFC 4180: a CSV field, quoted when it holds a comma, a quote or a line break.
#pragma once

#include <string>

namespace curdle {

inline std::string csv_field(const std::string& s) {
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
