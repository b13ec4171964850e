#include "curdle/error.h"

namespace curdle {
namespace {

// Built by appending: GCC 12 warns falsely (-Wrestrict) on chains of string concatenation.
std::string format(const SourceLocation& w, const std::string& message,
                   const ParameterNames& names) {
  std::string s = w.file;
  if (!w.parameter.empty()) {
    // A parameter that names a recipe key (an override) is written with it: "--set lattice.base".
    s = names ? names(w.parameter) : w.parameter;
    if (!s.empty() && !w.key.empty()) {
      s += ' ';
      s += w.key;
      s += ": ";
      s += message;
      return s;
    }
  }
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
  if (s.empty()) return message;
  s += ": ";
  s += message;
  return s;
}

}  // namespace

InputError::InputError(SourceLocation where, const std::string& message)
    : std::runtime_error(format(where, message, {})), where_(std::move(where)), message_(message) {}

InputError::InputError(const std::string& message)
    : std::runtime_error(message), message_(message) {}

std::string render_error(const InputError& error, const ParameterNames& names) {
  return format(error.where(), error.message(), names);
}

}  // namespace curdle
