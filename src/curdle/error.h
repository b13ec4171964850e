// User-facing errors. Bad input is an InputError carrying where it came from (file, line,
// column, key) and what is allowed; programmer mistakes are assertions. `main` turns
// InputError into exit code 2 and anything else into exit code 1.
#pragma once

#include <stdexcept>
#include <string>

namespace curdle {

struct SourceLocation {
  std::string file;  // recipe path, or "--set", or "command line"
  int line = 0;      // 1-based; 0 when unknown
  int column = 0;
  std::string key;  // dotted key path, e.g. "curds.0.probabilities"
};

class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& what)
      : std::runtime_error(format(where, what)), where_(std::move(where)) {}
  explicit InputError(const std::string& what) : std::runtime_error(what) {}

  const SourceLocation& where() const { return where_; }

 private:
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on chains of string concatenation.
  static std::string format(const SourceLocation& w, const std::string& what) {
    std::string s = w.file;
    if (w.line > 0) {
      s += ':';
      s += std::to_string(w.line);
      s += ':';
      s += std::to_string(w.column);
    }
    if (!w.key.empty()) {
      if (!s.empty()) s += ": ";
      s += "key '";
      s += w.key;
      s += '\'';
    }
    if (s.empty()) return what;
    s += ": ";
    s += what;
    return s;
  }
  SourceLocation where_;
};

}  // namespace curdle
