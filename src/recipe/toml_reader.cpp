#include "recipe/toml_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "curdle/palette.h"
#include "curdle/text.h"

namespace curdle::reading {
namespace {

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

SourceLocation locate(const Source& source, const toml::source_region& region,
                      const std::string& key) {
  for (const auto& o : source.overridden)
    if (key == o || key.rfind(o + ".", 0) == 0 || o.rfind(key + ".", 0) == 0)
      return parameter("set", key);
  SourceLocation where{source.file, 0, 0, key};
  where.line = static_cast<int>(region.begin.line);
  where.column = static_cast<int>(region.begin.column);
  return where;
}

int64_t read_int(TableReader& r, const std::string& key, int64_t fallback, int64_t lo, int64_t hi,
                 bool required) {
  const toml::node* n = r.get(key);
  if (!n) {
    if (required)
      r.fail(key, "is required: a whole number from " + std::to_string(lo) + " to " +
                      std::to_string(hi));
    return fallback;
  }
  const auto v = n->value<int64_t>();
  if (!n->is_integer() || !v || *v < lo || *v > hi)
    r.fail(key, "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return *v;
}

uint64_t read_seed(TableReader& r) {
  const toml::node* n = r.get("seed");
  if (!n) return 1;
  const std::string allowed =
      "must be a whole number from 0 to 18446744073709551615 (2^64 - 1); above "
      "9223372036854775807 write it in quotes, seed = \"18446744073709551615\"";
  if (n->is_integer()) {
    const int64_t v = *n->value<int64_t>();
    if (v < 0) r.fail("seed", allowed);
    return static_cast<uint64_t>(v);
  }
  if (!n->is_string()) r.fail("seed", allowed);
  const std::string text = *n->value<std::string>();
  uint64_t seed = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seed);
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0])) || ec != std::errc() ||
      end != text.data() + text.size())
    r.fail("seed", allowed);
  return seed;
}

std::optional<std::string> read_string(TableReader& r, const std::string& key,
                                       const std::string& allowed) {
  const toml::node* n = r.get(key);
  if (!n) return std::nullopt;
  if (!n->is_string()) r.fail(key, "must be a string in double quotes: " + allowed);
  std::string text = *n->value<std::string>();
  // Every string ends up in SVG, JSON, CSV and DXF: well-formed UTF-8 that shows as it reads.
  if (!valid_utf8(text)) r.fail(key, "is not valid UTF-8 text");
  if (has_control_characters(text))
    r.fail(key, "holds a control character; write plain text (tabs and line breaks allowed)");
  if (const std::string unsafe = unsafe_text(text);
      !unsafe.empty() && unsafe != "a line break or tab")
    r.fail(key, "holds " + unsafe + "; write plain text");
  if (text.size() > 4096) r.fail(key, "is longer than 4096 bytes");
  return text;
}

std::optional<std::string> read_name(TableReader& r, const std::string& key,
                                     const std::string& allowed) {
  std::optional<std::string> name = read_string(r, key, allowed);
  // A name is one line: in a DXF a line break would start a group code of its own.
  if (name && name->find_first_of("\t\r\n") != std::string::npos)
    r.fail(key, "holds a line break or tab; a name is one line of plain text");
  return name;
}

const toml::table* read_table(TableReader& r, const std::string& key) {
  const toml::node* n = r.get(key);
  if (!n) return nullptr;
  if (!n->is_table()) r.fail(key, "must be a table, written [" + key + "]");
  return n->as_table();
}

std::optional<Rgb> parse_colour(std::string_view s) { return parse_hex_colour(s); }

Probability read_probability(const TableReader& r, const toml::node& n, const std::string& path) {
  std::optional<Probability> p;
  if (n.is_string())
    p = Probability::parse(*n.value<std::string>());
  else if (n.is_integer())
    p = Probability::from_double(static_cast<double>(*n.value<int64_t>()));
  else if (n.is_floating_point())
    p = Probability::from_double(*n.value<double>());
  if (!p)
    r.fail_node(n, path,
                "a probability is a fraction like \"3/4\" or a decimal like \"0.75\", from 0 to 1");
  return *p;
}

std::optional<double> finite_number(const toml::node* node) {
  if (!node || !(node->is_integer() || node->is_floating_point())) return std::nullopt;
  const auto v = node->value<double>();
  if (!v || !std::isfinite(*v)) return std::nullopt;
  return v;
}

double read_mm(TableReader& r, const std::string& key, double fallback, double lo, bool required) {
  const toml::node* n = r.get(key);
  if (!n) {
    if (required) r.fail(key, "is required: a length in millimetres");
    return fallback;
  }
  const auto v = finite_number(n);
  if (!v || *v < lo || *v > 1e7)
    r.fail(key, "must be a length in millimetres from " + std::to_string(static_cast<int>(lo)) +
                    " to 10 km");
  return *v;
}

std::optional<std::array<double, 2>> read_mm_pair(TableReader& r, const std::string& key,
                                                  bool required) {
  const toml::node* n = r.get(key);
  if (!n) {
    if (required) r.fail(key, "is required: [width, height] in millimetres");
    return std::nullopt;
  }
  const toml::array* a = n->as_array();
  std::array<double, 2> v{};
  if (!a || a->size() != 2) r.fail(key, "must be [width, height] in millimetres");
  for (size_t i = 0; i < 2; ++i) {
    const auto x = finite_number(a->get(i));
    if (!x || *x < 1 || *x > 1e7)
      r.fail(key, "must be [width, height] in millimetres, each from 1 mm to 10 km");
    v[i] = *x;
  }
  return v;
}

bool read_bool(TableReader& r, const std::string& key, bool fallback) {
  const toml::node* n = r.get(key);
  if (!n) return fallback;
  if (!n->is_boolean()) r.fail(key, "must be true or false");
  return *n->value<bool>();
}

KeyDepth deepest_key(std::string_view text) {
  KeyDepth deepest;
  int parts = 1, line = 1;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      // A string, one line or three quotes: its dots are text, not key separators.
      const bool triple = text.substr(i, 3) == std::string(3, c);
      const std::string_view close = triple ? text.substr(i, 3) : text.substr(i, 1);
      size_t j = i + close.size();
      while (j < text.size() && text.substr(j, close.size()) != close) {
        if (c == '"' && text[j] == '\\') ++j;  // an escape: the next character is text
        if (j < text.size() && text[j] == '\n') ++line;
        ++j;
      }
      i = std::min(text.size(), j + close.size()) - 1;
      continue;
    }
    if (c == '#') {
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
    } else if (c == '.') {
      if (++parts > deepest.parts) deepest = {parts, line};
    } else if (c == '=' || c == ',' || c == '[' || c == ']' || c == '{' || c == '}' || c == '\n') {
      parts = 1;
      if (c == '\n') ++line;
    }
  }
  return deepest;
}

toml::table parse_toml(std::string_view text, const std::string& source) {
  // toml++ nests a table per part and recurses through them: a key of 60,000 parts overflows
  // the stack, so the parts are counted before it reads anything.
  if (const KeyDepth deep = deepest_key(text); deep.parts > kMostKeyParts)
    throw InputError(SourceLocation{source, deep.line, 1, ""},
                     "a dotted key or table header has " + std::to_string(deep.parts) +
                         " parts; at most " + std::to_string(kMostKeyParts) +
                         " (a recipe's deepest key, such as curds.0.density.values, has 4)");
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(SourceLocation{source, static_cast<int>(e.source().begin.line),
                                    static_cast<int>(e.source().begin.column), ""},
                     "not valid TOML: " + std::string(e.description()));
  }
}

std::optional<Rgb> read_colour(TableReader& r, const std::string& key) {
  const auto text = read_string(r, key, "a colour written \"#rrggbb\"");
  if (!text) return std::nullopt;
  const auto colour = parse_colour(*text);
  if (!colour) r.fail(key, "must be a colour written \"#rrggbb\", e.g. \"#c0392b\"");
  return colour;
}

void TableReader::reject_unknown() const {
  if (table_.empty()) return;
  for (auto&& [k, v] : table_) {
    const std::string key(k.str());
    if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
    std::string best;
    size_t best_d = 99;
    for (const auto& candidate : known_) {
      const size_t d = edit_distance(key, candidate);
      if (d < best_d) best_d = d, best = candidate;
    }
    std::string msg = "unknown key '" + key + "'";
    if (best_d <= std::max<size_t>(2, key.size() / 3))
      msg += "; did you mean '" + best + "'?";
    else
      msg += ".";
    msg += " Allowed here: " + join(known_) + ".";
    throw InputError(locate(source_, v.source(), key_path(key)), msg);
  }
}

std::vector<std::string> TableReader::never_asked() const {
  std::vector<std::string> keys;
  for (const std::string& k : known_)
    if (!asked_.count(k)) keys.push_back(k);
  return keys;
}

void TableReader::report_unused(const std::string& why) const {
  for (auto&& [k, v] : table_) {
    const std::string key(k.str());
    if (!asked_.count(key))
      throw InputError(locate(source_, v.source(), key_path(key)),
                       "'" + key + "' " + why + ". Read here: " +
                           join(std::vector<std::string>(asked_.begin(), asked_.end())) + ".");
  }
}

}  // namespace curdle::reading
