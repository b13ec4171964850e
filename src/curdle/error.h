// User-facing errors. Bad input is an InputError carrying where it came from (recipe file, line,
// column and key, or a run parameter) and what is allowed; programmer mistakes are assertions.
//
// The core names run parameters neutrally ("window", "seed", "max_memory"); each shell renders
// them in its own words (`--window` on the command line, `window=` in the API) through
// render_error. A resource limit is its own type: exit 2 on the command line, HTTP 413 in the API.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace curdle {

struct SourceLocation {
  std::string file;  // recipe path; empty for a run parameter
  int line = 0;      // 1-based; 0 when unknown
  int column = 0;
  std::string key;        // dotted recipe key, e.g. "curds.0.probabilities"
  std::string parameter;  // neutral run parameter: "window", "seed", "set" (an override), ...
};

// Where a run parameter's value was wrong.
inline SourceLocation parameter(std::string name, std::string key = {}) {
  SourceLocation where;
  where.parameter = std::move(name);
  where.key = std::move(key);
  return where;
}

class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& message);
  explicit InputError(const std::string& message);

  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }  // without the location

 private:
  SourceLocation where_;
  std::string message_;
};

// A request above a limit (memory, cells, seeds, work): what is allowed and how to raise it.
class ResourceLimitError : public InputError {
 public:
  using InputError::InputError;
};

// How a shell spells a run parameter: "--window" or "window=".
using ParameterNames = std::function<std::string(const std::string& parameter)>;

// "file:line:column: key 'k': message", with a parameter spelt by `names` (neutral: as is).
std::string render_error(const InputError& error, const ParameterNames& names = {});

}  // namespace curdle
