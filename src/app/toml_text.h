// Text a fitted recipe is written in.
#pragma once

#include <fmt/format.h>

#include <string>

namespace curdle::app {

// A TOML basic string: quotes, backslashes and control characters escaped, so that no name
// (a curd's or a state's, from a cells.csv) can end the string and write keys of its own.
inline std::string toml_quoted(const std::string& s) {
  std::string q = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\')
      q += '\\', q += ch;
    else if (c < 0x20 || c == 0x7F)
      q += fmt::format("\\u{:04X}", c);
    else
      q += ch;
  }
  return q + '"';
}

}  // namespace curdle::app
