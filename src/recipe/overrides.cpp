#include "recipe/overrides.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>

#include "curdle/error.h"
#include "recipe/recipe.h"
#include "recipe/toml_reader.h"

namespace curdle {
namespace reading {

void apply_override(toml::table& doc, const std::string& assignment) {
  const auto eq = assignment.find('=');
  const std::string key = assignment.substr(0, eq);
  if (eq == std::string::npos || key.empty())
    throw InputError(parameter("set", key), "expects KEY=VALUE, e.g. lattice.mode=exact");
  const std::string value = assignment.substr(eq + 1);
  const std::string source = "override " + key;
  if (deepest_key(key).parts > kMostKeyParts || deepest_key(value).parts > kMostKeyParts)
    throw InputError(parameter("set", key.substr(0, 200)),
                     "has a dotted key of more than " + std::to_string(kMostKeyParts) +
                         " parts; at most " + std::to_string(kMostKeyParts) +
                         " (a recipe's deepest key, such as curds.0.density.values, has 4)");
  // Each part a bare key: a line break or quote in a key would smuggle in a second assignment.
  const bool bare = std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
  if (!bare || key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos)
    throw InputError(parameter("set", key.substr(0, 200)),
                     "is not a recipe key: write dotted parts of letters, digits, _ and -, "
                     "e.g. lattice.base or curds.0.probabilities");
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value, source);
  } catch (const toml::parse_error&) {
    parsed = toml::parse("v = \"\"", source);  // a bare word is a string
    parsed.insert_or_assign("v", value);
  }
  if (parsed.size() != 1)
    throw InputError(parameter("set", key),
                     "holds more than one value (a line break followed by another key?); "
                     "give one TOML value, e.g. 3, \"exact\" or [1, 2]");
  const toml::node& v = *parsed.get("v");

  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t dot = key.find('.', start);
    parts.push_back(key.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  toml::node* at = &doc;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    const std::string& part = parts[i];
    if (auto* t = at->as_table()) {
      if (!t->get(part)) {
        const bool next_is_index = std::all_of(parts[i + 1].begin(), parts[i + 1].end(), ::isdigit);
        if (next_is_index)
          throw InputError(parameter("set", key), "'" + part + "' has no such entry");
        t->insert_or_assign(part, toml::table{});
      }
      at = t->get(part);
    } else if (auto* a = at->as_array()) {
      size_t idx = 0;
      auto [p, ec] = std::from_chars(part.data(), part.data() + part.size(), idx);
      if (ec != std::errc() || p != part.data() + part.size() || idx >= a->size())
        throw InputError(parameter("set", key),
                         "index '" + part + "' is out of range; the array has " +
                             std::to_string(a->size()) + " entries (from 0)");
      at = a->get(idx);
    } else {
      throw InputError(parameter("set", key), "'" + part + "' is not a table or array");
    }
  }
  const std::string& last = parts.back();
  if (auto* t = at->as_table()) {
    v.visit([&](auto&& x) { t->insert_or_assign(last, x); });
  } else if (auto* a = at->as_array()) {
    size_t idx = 0;
    auto [p, ec] = std::from_chars(last.data(), last.data() + last.size(), idx);
    // The whole part is the index: "0abc" is no index.
    if (ec != std::errc() || p != last.data() + last.size() || idx >= a->size())
      throw InputError(parameter("set", key), "index '" + last +
                                                  "' is not an entry; the array has " +
                                                  std::to_string(a->size()) + " entries (from 0)");
    v.visit([&](auto&& x) { a->replace(a->cbegin() + static_cast<ptrdiff_t>(idx), x); });
  } else {
    throw InputError(parameter("set", key), "cannot set a key inside a value");
  }
}

}  // namespace reading

namespace {

bool is_file_key(std::string_view key) { return key == "mask" || key == "path" || key == "file"; }

bool holds_file_key(const toml::node& node) {
  if (const toml::table* t = node.as_table())
    for (const auto& [k, v] : *t)
      if (is_file_key(k.str()) || holds_file_key(v)) return true;
  if (const toml::array* a = node.as_array())
    for (const toml::node& v : *a)
      if (holds_file_key(v)) return true;
  return false;
}

}  // namespace

bool override_names_a_file(const std::string& assignment) {
  const std::string key = assignment.substr(0, assignment.find('='));
  for (size_t start = 0;;) {
    const size_t dot = key.find('.', start);
    if (is_file_key(key.substr(start, dot - start))) return true;
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (assignment.find('=') == std::string::npos) return false;
  if (reading::deepest_key(assignment).parts > reading::kMostKeyParts) return false;  // refused
  try {
    const toml::table parsed = toml::parse("v = " + assignment.substr(assignment.find('=') + 1));
    return holds_file_key(*parsed.get("v"));
  } catch (const toml::parse_error&) {
    return false;  // a bare word: a string, which holds no key
  }
}

std::string recipe_text_with(std::string_view text, const std::string& source,
                             const std::vector<std::string>& overrides) {
  toml::table doc = reading::parse_toml(text, source);
  for (const auto& o : overrides) reading::apply_override(doc, o);
  std::ostringstream out;
  out << doc << "\n";
  return out.str();
}

}  // namespace curdle
